// Faults in plan files (docs/PLAN_FORMAT.md): truncated text, wrong types, non-finite numbers,
// wrong dimensions and unknown surface ids are InputErrors naming the file and the field, and
// `stanceplan certify` exits 1 on them. The base plan is the fuzz seed fuzz/corpus/plan/
// walk_initial.json (a real one-step plan of humanoid_walk.yaml).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "planner/io/plan_reader.h"
#include "planner/util/input_error.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The seed plan with its model paths made absolute, so that copies can be written anywhere.
json seed_plan() {
  std::ifstream in(test::source_path("fuzz/corpus/plan/walk_initial.json"));
  json plan = json::parse(in);
  for (json& e : plan["entities"]) {
    e["urdf"] = test::source_path("fuzz/corpus/plan/" + e["urdf"].get<std::string>());
    e["surfaces_file"] =
        test::source_path("fuzz/corpus/plan/" + e["surfaces_file"].get<std::string>());
  }
  return plan;
}

std::string write_text(const std::string& name, const std::string& text) {
  const std::string path = (test::temp_dir("plan_faults") / name).string();
  std::ofstream(path) << text;
  return path;
}

// Writes the seed plan changed by `change` and returns the reader's error ("" when it loads).
std::string error_of(const std::function<void(json&)>& change, const std::string& name,
                     std::string* path_out = nullptr) {
  json plan = seed_plan();
  change(plan);
  const std::string path = write_text(name + ".json", plan.dump(1));
  if (path_out) *path_out = path;
  try {
    read_plan(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The field message after "FILE: ".
std::string field_error(const std::function<void(json&)>& change, const std::string& name) {
  std::string path;
  const std::string error = error_of(change, name, &path);
  EXPECT_THAT(error, StartsWith(path + ": "));
  return error.substr(std::min(error.size(), path.size() + 2));
}

TEST(PlanFileFaults, TheSeedPlanLoadsAndCertifies) {
  const std::string path = write_text("seed.json", seed_plan().dump(1));
  const test::CliResult r = test::run_cli({"certify", path});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("all checks passed"));
}

TEST(PlanFileFaults, ATruncatedFileIsNotValidJson) {
  const std::string text = seed_plan().dump(1);
  const std::string path = write_text("truncated.json", text.substr(0, text.size() / 2));
  const test::CliResult r = test::run_cli({"certify", path});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, StartsWith("stanceplan: error: " + path + ": not valid JSON: "));
  EXPECT_THAT(r.err, HasSubstr("parse error at line "));
  const std::string empty = write_text("empty.json", "");
  EXPECT_THROW(read_plan(empty), InputError);
}

TEST(PlanFileFaults, WrongTypesNameTheFieldAndWhatWasFound) {
  EXPECT_EQ(
      field_error(
          [](json& p) { p["steps"][0]["configuration"]["robot"]["joints"]["l_knee_p"] = "0.5"; },
          "joint_string"),
      "steps[0].configuration.robot.joints.l_knee_p: expected a number, found a string");
  EXPECT_EQ(
      field_error([](json& p) { p["steps"][0]["contacts"][0]["loaded"] = "yes"; }, "loaded_string"),
      "steps[0].contacts[0].loaded: expected true or false, found a string");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["contacts"][0] = 7; }, "contact_number"),
            "steps[0].contacts[0]: expected an object, found a number");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0] = json::array(); }, "step_array"),
            "steps[0]: expected an object, found an array of 0");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["solver"]["iterations"] = "many"; },
                        "iterations_string"),
            "steps[0].solver.iterations: expected a number, found a string");
  EXPECT_EQ(field_error([](json& p) { p["stats"]["threads"] = 1.5; }, "threads_fraction"),
            "stats.threads: expected a whole number >= 0, found 1.5");
  EXPECT_EQ(field_error([](json& p) { p["stats"] = "fast"; }, "stats_string"),
            "stats: expected an object, found a string");
  EXPECT_EQ(field_error(
                [](json& p) { p["steps"][0]["configuration"]["robot"]["joints"] = json::array(); },
                "joints_array"),
            "steps[0].configuration.robot.joints: expected an object, found an array of 0");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["torques"] = 3; }, "torques_number"),
            "steps[0].torques: expected an object, found a number");
  EXPECT_EQ(field_error([](json& p) { p = json::array(); }, "top_array"),
            "expected an object, found an array of 0");
}

TEST(PlanFileFaults, NonFiniteNumbersAreRejected) {
  // JSON has no NaN or infinity: the literal is a syntax error, and a number too large for a
  // double is out of range.
  std::string text = seed_plan().dump(1);
  const std::string gravity = "-9.81";
  text.replace(text.find(gravity), gravity.size(), "NaN");
  const std::string path = write_text("nan.json", text);
  try {
    read_plan(path);
    ADD_FAILURE() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(path + ": not valid JSON: "));
  }
  std::string huge = seed_plan().dump(1);
  huge.replace(huge.find(gravity), gravity.size(), "-1e999");
  const std::string huge_path = write_text("huge.json", huge);
  EXPECT_THROW(read_plan(huge_path), InputError);
  EXPECT_EQ(field_error([](json& p) { p["gravity"][2] = "NaN"; }, "nan_string"),
            "gravity[2]: expected a number, found a string");
}

TEST(PlanFileFaults, WrongDimensionsAreNamed) {
  EXPECT_EQ(field_error(
                [](json& p) {
                  p["gravity"] = {0.0, -9.81};
                },
                "gravity_2"),
            "gravity: expected [x, y, z], found an array of 2");
  EXPECT_EQ(
      field_error(
          [](json& p) {
            p["steps"][0]["configuration"]["robot"]["base_orientation_wxyz"] = {1.0, 0.0, 0.0};
          },
          "quaternion_3"),
      "steps[0].configuration.robot.base_orientation_wxyz: expected [w, x, y, z]");
  EXPECT_EQ(field_error(
                [](json& p) {
                  p["steps"][0]["forces"][0]["force_world"] = {1.0, 2.0, 3.0, 4.0};
                },
                "force_4"),
            "steps[0].forces[0].force_world: expected [x, y, z], found an array of 4");
  EXPECT_EQ(
      field_error(
          [](json& p) { p["steps"][0]["configuration"]["robot"]["joints"].erase("l_knee_p"); },
          "joint_missing"),
      "steps[0].configuration.robot.joints: missing joint \"l_knee_p\"");
  EXPECT_EQ(field_error(
                [](json& p) {
                  p["surfaces"][0]["rotation"] = {{1.0, 0.0, 0.0}};
                },
                "rotation_1"),
            "surfaces[0].rotation: expected a 3x3 array of rows");
}

TEST(PlanFileFaults, UnknownSurfaceIdsAndEntitiesAreNamed) {
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["stance"][0]["s1"] = "robot/l_sole_typo"; },
                        "surface_typo"),
            "steps[0].stance[0].s1: no surface \"robot/l_sole_typo\" in the plan's surfaces");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["contacts"][1]["s2"] = "ghost/floor"; },
                        "surface_entity"),
            "steps[0].contacts[1].s2: no surface \"ghost/floor\" in the plan's surfaces");
  EXPECT_EQ(field_error([](json& p) { p["surfaces"][0]["entity"] = "ghost"; }, "entity_unknown"),
            "surfaces[0].entity: no entity \"ghost\"");
  EXPECT_EQ(field_error([](json& p) { p["steps"][0]["action"] = "jump"; }, "action"),
            "steps[0].action: expected initial, add or remove, found \"jump\"");
}

// Format @2: the motion into a step (docs/PLAN_FORMAT.md, `motion`).
TEST(PlanFileFaults, MotionFieldsAreNamed) {
  EXPECT_EQ(field_error([](json& p) { p["format"] = "stanceplan/plan@3"; }, "format_3"),
            "format: expected \"stanceplan/plan@1\" or \"stanceplan/plan@2\", found "
            "\"stanceplan/plan@3\"");
  const auto with_motion = [](const json& motion) {
    return [motion](json& p) {
      p["format"] = "stanceplan/plan@2";
      p["steps"].push_back(p["steps"][0]);
      p["steps"][1]["motion"] = motion;
    };
  };
  EXPECT_EQ(field_error(
                [](json& p) {
                  p["steps"][0]["motion"] = {{"status", "solved"}, {"samples", json::array()}};
                },
                "motion_step_0"),
            "steps[0].motion: step 0 has no motion into it");
  EXPECT_EQ(
      field_error(with_motion({{"status", "flying"}, {"samples", json::array()}}), "motion_status"),
      "steps[1].motion.status: expected solved, projection_failed, spacing_not_reached or "
      "ends_disagree, found \"flying\"");
  EXPECT_EQ(field_error(with_motion({{"status", "solved"}}), "motion_samples"),
            "steps[1].motion.samples: missing");
  EXPECT_EQ(field_error(with_motion({{"status", "solved"}, {"samples", {{{"forces", 1}}}}}),
                        "motion_sample"),
            "steps[1].motion.samples[0].configuration: missing");
  EXPECT_EQ(error_of(with_motion({{"status", "solved"}, {"samples", json::array()}}), "motion_ok"),
            "");
}

TEST(PlanFileFaults, TheCertifyCommandExitsOneOnEveryFault) {
  std::string path;
  error_of([](json& p) { p["steps"][0]["contacts"][0]["fixed"] = 1; }, "fixed_number", &path);
  const test::CliResult r = test::run_cli({"certify", path});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: " + path +
                       ": steps[0].contacts[0].fixed: expected true or false, found a number\n");
}

}  // namespace
}  // namespace stanceplan
