#pragma once
// One input of each fuzz target, shared by the libFuzzer entry points (fuzz/*_fuzz.cpp) and the
// regression test that replays the inputs the fuzzers found (tests/robustness). Each function
// writes the bytes to a file inside a work folder laid out like the source tree, so that the
// relative paths in the seeds (scenarios/*.yaml, fuzz/corpus/plan/*.json) still resolve, and runs
// the loader on it. Bad input must end in an InputError; anything else that escapes (another
// exception, a crash, a sanitizer report) is a finding.
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "planner/certify/certify.h"
#include "planner/collision/collision_model.h"
#include "planner/contact/surface_file.h"
#include "planner/io/plan_reader.h"
#include "planner/io/request_file.h"
#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/model/system.h"
#include "planner/model/urdf_loader.h"
#include "planner/solver/posture_solver.h"
#include "planner/util/input_error.h"

namespace stanceplan::fuzz {

enum class Target { Scenario, Surfaces, Plan, Urdf, Srdf, Request };

struct Outcome {
  bool accepted = false;  // the loader took the input
  std::string error;      // the InputError's message when it did not
};

inline std::filesystem::path source_dir() {
  return STANCEPLAN_SOURCE_DIR;
}

// Prepares `work`: work/assets links to this source tree's assets. A folder of the same name may
// be left from an earlier process with the same id (ids are reused), its link dangling or pointing
// at another checkout: the link is made anew.
inline void prepare_work_dir(const std::filesystem::path& work) {
  namespace fs = std::filesystem;
  for (const char* sub : {"scenarios", "fuzz/corpus/plan"}) fs::create_directories(work / sub);
  std::error_code ec;
  fs::remove(work / "assets", ec);
  fs::create_directory_symlink(source_dir() / "assets", work / "assets");
}

// Where an input of `target` is written inside the work folder (the depth the seeds expect).
inline std::filesystem::path input_path(Target target, const std::filesystem::path& work) {
  switch (target) {
    case Target::Scenario:
      return work / "scenarios" / "input.yaml";
    case Target::Surfaces:
      return work / "input.surfaces.yaml";
    case Target::Plan:
      return work / "fuzz" / "corpus" / "plan" / "input.json";
    case Target::Urdf:
      return work / "input.urdf";
    case Target::Srdf:
      return work / "input.srdf";
    case Target::Request:
      return work / "input.bin";
  }
  return work / "input";
}

inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The models surface files are read against: the humanoid and every environment of assets/.
inline const std::vector<std::shared_ptr<const Model>>& surface_models() {
  static const std::vector<std::shared_ptr<const Model>> models = [] {
    std::vector<std::shared_ptr<const Model>> out;
    for (const char* urdf :
         {"robots/humanoid/humanoid.urdf", "environments/desk_room/desk_room.urdf",
          "environments/flat_ground/flat_ground.urdf", "environments/wall/wall.urdf"})
      out.push_back(std::make_shared<Model>(load_urdf((source_dir() / "assets" / urdf).string())));
    return out;
  }();
  return models;
}

// The humanoid as a floating entity "robot": what an SRDF's disabled pairs are applied to.
inline const System& srdf_system() {
  static const System system = [] {
    System out;
    Entity entity;
    entity.name = "robot";
    entity.kind = EntityKind::FloatingRobot;
    entity.model = std::make_shared<Model>(
        load_urdf((source_dir() / "assets" / "robots" / "humanoid" / "humanoid.urdf").string()));
    out.add(std::move(entity));
    return out;
  }();
  return system;
}

// A model that loads is also put through what a scene does with it: a floating entity, forward
// kinematics and centre of mass at the neutral configuration, and its collision model.
inline void use_model(Model model) {
  System system;
  Entity entity;
  entity.name = "robot";
  entity.kind = EntityKind::FloatingRobot;
  entity.model = std::make_shared<Model>(std::move(model));
  const int e = system.add(std::move(entity));
  const std::vector<ModelData> data = system_kinematics(system, system.neutral_configuration());
  (void)center_of_mass(system.entity(e), data[e]);
  CollisionModel collision(system);
  (void)collision;
}

// A request file (stanceplan replay) read, then solved for a few iterations on the scene the seeds
// were written for (the untuned side-step: the humanoid on the floor): a request that does not fit
// it is refused by the solver's checks (std::invalid_argument), as replay refuses it.
inline void replay_request(const std::filesystem::path& path) {
  static const Scenario scenario =
      load_scenario((source_dir() / "scenarios" / "untuned" / "side_step.yaml").string());
  const PostureRequest request = read_request_file(path.string());
  SolverOptions options = scenario.solver;
  options.max_iterations = 3;
  try {
    (void)PostureSolver(scenario.scene, options).solve(request);
  } catch (const std::invalid_argument& e) {
    throw InputError(path.string() + ": does not fit the scene: " + e.what());
  }
}

inline Outcome run_one(Target target, std::string_view bytes, const std::filesystem::path& work) {
  const std::filesystem::path path = input_path(target, work);
  write_bytes(path, bytes);
  Outcome outcome;
  try {
    switch (target) {
      case Target::Scenario:
        (void)load_scenario(path.string());
        break;
      case Target::Surfaces:
        // Accepted when it is a valid surface file of at least one of the models.
        for (const auto& model : surface_models()) {
          try {
            (void)load_surface_file(path.string(), *model);
            outcome.accepted = true;
          } catch (const InputError& e) {
            outcome.error = e.what();
          }
        }
        return outcome;
      case Target::Plan:
        (void)certify(read_plan(path.string()));
        break;
      case Target::Urdf: {
        UrdfOptions options;
        options.packages.directories = {(work / "assets").string()};
        options.packages.use_ros_package_path = false;
        use_model(load_urdf_string(std::string(bytes),
                                   (work / "assets" / "robots" / "humanoid").string(), options,
                                   path.string()));
        break;
      }
      case Target::Request:
        replay_request(path);
        break;
      case Target::Srdf: {
        // The loader, then what the collision model does with its pairs.
        CollisionOptions options;
        options.srdf_files = {{"robot", path.string()}};
        CollisionModel collision(srdf_system(), options);
        (void)collision;
        break;
      }
    }
    outcome.accepted = true;
  } catch (const InputError& e) {
    outcome.error = e.what();
  }
  return outcome;
}

}  // namespace stanceplan::fuzz
