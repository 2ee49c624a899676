// package:// resolution as ../shared/robots/README.md specifies it.
#include <gtest/gtest.h>

#include "tests/support/paths.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "planner/model/package_path.h"

namespace stanceplan {
namespace {
namespace fs = std::filesystem;

class PackagePathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::temp_dir("pkg");
    fs::remove_all(root_);
    touch(root_ / "one/robotpkg/meshes/a.stl");  // DIR/NAME/REST
    touch(root_ / "two/meshes/a.stl");           // DIR/REST
    touch(root_ / "two/meshes/b.stl");
  }
  static void touch(const fs::path& p) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
  }
  fs::path root_;
};

TEST_F(PackagePathTest, FirstDirectoryWinsAndNameIsOptional) {
  PackagePath packages;
  packages.use_ros_package_path = false;
  packages.directories = {(root_ / "one").string(), (root_ / "two").string()};
  EXPECT_EQ(resolve_uri("package://robotpkg/meshes/a.stl", "/", packages),
            (root_ / "one/robotpkg/meshes/a.stl").string());
  EXPECT_EQ(resolve_uri("package://robotpkg/meshes/b.stl", "/", packages),
            (root_ / "two/meshes/b.stl").string());
  std::vector<std::string> tried;
  EXPECT_FALSE(resolve_uri("package://robotpkg/meshes/c.stl", "/", packages, &tried));
  EXPECT_EQ(tried.size(), 4u);
}

TEST_F(PackagePathTest, RosPackagePathIsSearchedAfterExplicitDirectories) {
  setenv("ROS_PACKAGE_PATH", (root_ / "two").string().c_str(), 1);
  PackagePath packages;
  EXPECT_EQ(resolve_uri("package://x/meshes/b.stl", "/", packages),
            (root_ / "two/meshes/b.stl").string());
  packages.use_ros_package_path = false;
  EXPECT_FALSE(resolve_uri("package://x/meshes/b.stl", "/", packages));
  unsetenv("ROS_PACKAGE_PATH");
}

TEST_F(PackagePathTest, RelativeAndFileUrisAreRelativeToTheUrdf) {
  PackagePath packages;
  EXPECT_EQ(resolve_uri("meshes/a.stl", (root_ / "two").string(), packages),
            (root_ / "two/meshes/a.stl").string());
  EXPECT_EQ(resolve_uri("file://" + (root_ / "two/meshes/a.stl").string(), "/nowhere", packages),
            (root_ / "two/meshes/a.stl").string());
}

}  // namespace
}  // namespace stanceplan
