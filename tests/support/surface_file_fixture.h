#pragma once
// A surface file written from a test's text (after the format line and `surfaces:`) and loaded
// against tests/data/link_faces/faces.urdf; error_of() gives the InputError's message.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

namespace stanceplan::test {

class SurfaceFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = load_urdf(source_path("tests/data/link_faces/faces.urdf"));
    path_ =
        (temp_dir("surface_files") /
         (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".yaml"))
            .string();
  }
  std::vector<Surface> load(const std::string& surfaces) {
    std::ofstream(path_) << "format: stanceplan/surfaces@1\nsurfaces:\n" << surfaces;
    return load_surface_file(path_, model_);
  }
  // The message of the InputError the surfaces (from line 3 of the file) raise.
  std::string error_of(const std::string& surfaces) {
    try {
      load(surfaces);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  Model model_;
  std::string path_;
};

}  // namespace stanceplan::test
