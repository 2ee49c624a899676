// `configuration: {srdf_state: NAME, ...}`: the entity's SRDF group state applied first, the
// scenario's own base pose and joints over it, in entities[i].configuration and in milestones;
// and every fault with its exact message. TALOS's half_sitting (../shared) is checked against
// the SRDF's numbers read by a regular expression, not by the SRDF reader.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "planner/io/scenario.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

// Three states for the humanoid of assets/: "crouch" (two knees, a hip), "free" (a floating base
// as Pinocchio writes it, x y z qx qy qz qw) and "arms" twice, for two groups.
const char* kSrdf = R"(<?xml version="1.0"?>
<robot name="humanoid">
  <group_state name="crouch" group="legs">
    <joint name="l_knee_p" value="0.8"/>
    <joint name="r_knee_p" value="0.7"/>
    <joint name="l_hip_p" value="-0.4"/>
  </group_state>
  <group_state name="free" group="all">
    <joint name="root_joint" value="0.1 0.2 0.85 0 0 0.7071067811865476 0.7071067811865476"/>
    <joint name="chest_p" value="0.1"/>
  </group_state>
  <group_state name="arms" group="left_arm">
    <joint name="l_elbow_p" value="-1"/>
  </group_state>
  <group_state name="arms" group="right_arm">
    <joint name="r_elbow_p" value="-1.5"/>
  </group_state>
</robot>
)";

class SrdfState : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("srdf_state");
    name_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    srdf_ = write(name_ + ".srdf", kSrdf);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // The humanoid on flat ground; `robot` holds extra lines of the robot entity (srdf,
  // configuration) at line 7 onwards, `rest` follows the stances.
  std::string scenario(const std::string& robot, const std::string& rest = "") const {
    const std::string assets = test::source_path("assets");
    const std::string env = assets + "/environments/flat_ground/flat_ground";
    return write(name_ + ".yaml",
                 "format: stanceplan/scenario@1\n"
                 "entities:\n"
                 "  - name: robot\n"
                 "    kind: floating\n"
                 "    urdf: " +
                     assets + "/robots/humanoid/humanoid.urdf\n    surfaces: " + assets +
                     "/robots/humanoid/humanoid.surfaces.yaml\n" + robot +
                     "  - name: env\n    kind: environment\n    urdf: " + env +
                     ".urdf\n    surfaces: " + env +
                     ".surfaces.yaml\n"
                     "stances:\n"
                     "  initial: [{s1: robot/l_sole, s2: env/floor}]\n"
                     "  goal: [{s1: robot/r_sole, s2: env/floor}]\n" +
                     rest);
  }
  std::string error_of(const std::string& path) const {
    try {
      load_scenario(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  // The value of `joint` of the robot (entity 0) in q.
  static double joint(const Scenario& s, const Eigen::VectorXd& q, const std::string& name) {
    const Entity& robot = s.scene.system.entity(0);
    const int dof = robot.model->find_dof(name);
    EXPECT_GE(dof, 0) << name;
    return q[s.scene.system.offset(0) + robot.first_dof() + dof];
  }
  std::filesystem::path dir_;
  std::string name_, srdf_;
};

TEST_F(SrdfState, TheStateIsAppliedAndTheExplicitJointsOverrideIt) {
  const Scenario s =
      load_scenario(scenario("    srdf: " + srdf_ +
                             "\n    configuration: {srdf_state: crouch, base_position: [0, 0, 0.9],"
                             " joints: {r_knee_p: 0.3}}\n"));
  const Eigen::VectorXd& q = s.initial_configuration;
  EXPECT_EQ(joint(s, q, "l_knee_p"), 0.8);
  EXPECT_EQ(joint(s, q, "l_hip_p"), -0.4);
  EXPECT_EQ(joint(s, q, "r_knee_p"), 0.3);  // the scenario's value wins
  EXPECT_EQ(joint(s, q, "chest_p"), 0.0);   // not in the state: neutral
  EXPECT_EQ(q.segment<3>(0), Eigen::Vector3d(0, 0, 0.9));
}

TEST_F(SrdfState, AFloatingBaseInTheStatePlacesTheBase) {
  const Scenario s =
      load_scenario(scenario("    srdf: " + srdf_ + "\n    configuration: {srdf_state: free}\n"));
  const Eigen::VectorXd& q = s.initial_configuration;
  EXPECT_EQ(q.segment<3>(0), Eigen::Vector3d(0.1, 0.2, 0.85));
  // x y z qx qy qz qw in the SRDF; w x y z in a configuration.
  EXPECT_NEAR(q[3], 0.7071067811865476, 1e-15);
  EXPECT_NEAR(q[6], 0.7071067811865476, 1e-15);
  EXPECT_EQ(q[4], 0.0);
  EXPECT_EQ(q[5], 0.0);
  EXPECT_EQ(joint(s, q, "chest_p"), 0.1);
}

TEST_F(SrdfState, ANameGivenForTwoGroupsAppliesBoth) {
  const Scenario s = load_scenario(
      scenario("    srdf: " + srdf_ +
               "\n    configuration: {srdf_state: arms, base_position: [0, 0, 0.9]}\n"));
  EXPECT_EQ(joint(s, s.initial_configuration, "l_elbow_p"), -1.0);
  EXPECT_EQ(joint(s, s.initial_configuration, "r_elbow_p"), -1.5);
}

TEST_F(SrdfState, AMilestoneStatesTheJointsOfItsState) {
  const Scenario s = load_scenario(
      scenario("    srdf: " + srdf_ + "\n    configuration: {base_position: [0, 0, 0.9]}\n",
               "guide:\n  - robot: {srdf_state: crouch, joints: {l_hip_p: -0.2}}\n"));
  ASSERT_EQ(s.milestones.size(), 1u);
  const Eigen::VectorXd& q = s.milestones[0];
  EXPECT_EQ(joint(s, q, "l_knee_p"), 0.8);
  EXPECT_EQ(joint(s, q, "r_knee_p"), 0.7);
  EXPECT_EQ(joint(s, q, "l_hip_p"), -0.2);
  EXPECT_EQ(joint(s, s.milestone_masks[0], "l_knee_p"), 1.0);               // stated by the state
  EXPECT_EQ(joint(s, s.milestone_masks[0], "chest_p"), 0.0);                // left free
  EXPECT_EQ(s.milestone_masks[0].segment<7>(0), Eigen::VectorXd::Zero(7));  // base not stated
}

TEST_F(SrdfState, AnEntityWithoutSrdf) {
  const std::string path = scenario("    configuration: {srdf_state: crouch}\n");
  EXPECT_EQ(error_of(path), path +
                                ":7: entities[0].configuration.srdf_state: entity \"robot\" has "
                                "no srdf (give its srdf: FILE to use a group state)");
}

TEST_F(SrdfState, AnUnknownStateListsTheKnownOnes) {
  const std::string path =
      scenario("    srdf: " + srdf_ + "\n    configuration: {srdf_state: half_sitting}\n");
  EXPECT_EQ(error_of(path), path + ":8: entities[0].configuration.srdf_state: no group_state " +
                                "\"half_sitting\" in " + srdf_ + " (it has: crouch, free, arms)");
}

TEST_F(SrdfState, AStateJointTheModelLacks) {
  const std::string srdf = write("ghost.srdf", R"(<robot name="humanoid">
  <group_state name="s" group="g">
    <joint name="l_knee_p" value="0.1"/>
    <joint name="tail_joint" value="0.2"/>
  </group_state>
</robot>)");
  const std::string path = scenario("    srdf: " + srdf + "\n    configuration: {srdf_state: s}\n");
  EXPECT_EQ(error_of(path),
            path + ":8: entities[0].configuration.srdf_state: " + srdf +
                ":4: group_state \"s\": joint \"tail_joint\": model \"humanoid\" (" +
                test::source_path("assets") + "/robots/humanoid/humanoid.urdf) has no such joint");
}

TEST_F(SrdfState, SeveralValuesForAOneDofJoint) {
  const std::string srdf = write("multi.srdf", R"(<robot name="humanoid">
  <group_state name="s" group="g"><joint name="l_knee_p" value="0.1 0.2"/></group_state>
</robot>)");
  const std::string path = scenario("    srdf: " + srdf + "\n    configuration: {srdf_state: s}\n");
  EXPECT_EQ(error_of(path), path + ":8: entities[0].configuration.srdf_state: " + srdf +
                                ":2: group_state \"s\": joint \"l_knee_p\": expected one value "
                                "(the joint has one degree of freedom), found 2 (multi-dof joints "
                                "other than the floating base are not supported)");
}

TEST_F(SrdfState, AFloatingBaseWithTheWrongNumberOfValues) {
  const std::string srdf = write("base.srdf", R"(<robot name="humanoid">
  <group_state name="s" group="g"><joint name="root_joint" value="0 0 1"/></group_state>
</robot>)");
  const std::string path = scenario("    srdf: " + srdf + "\n    configuration: {srdf_state: s}\n");
  EXPECT_EQ(error_of(path), path + ":8: entities[0].configuration.srdf_state: " + srdf +
                                ":2: group_state \"s\": joint \"root_joint\": expected 7 values "
                                "for the floating base (x y z qx qy qz qw), found 3");
}

TEST_F(SrdfState, AValueOutsideTheJointLimits) {
  const std::string srdf = write("limits.srdf", R"(<robot name="humanoid">
  <group_state name="s" group="g"><joint name="l_knee_p" value="-0.5"/></group_state>
</robot>)");
  const std::string path = scenario("    srdf: " + srdf + "\n    configuration: {srdf_state: s}\n");
  EXPECT_EQ(error_of(path), path + ":8: entities[0].configuration.srdf_state: " + srdf +
                                ":2: group_state \"s\": joint \"l_knee_p\": -0.500000 is outside "
                                "the joint's limits [0.000000, 2.500000]");
}

TEST_F(SrdfState, AValueThatIsNotANumber) {
  const std::string srdf = write("nan.srdf", R"(<robot name="humanoid">
  <group_state name="s" group="g">
    <joint name="l_knee_p" value="nan"/>
  </group_state>
</robot>)");
  const std::string path = scenario("    srdf: " + srdf + "\n    configuration: {srdf_state: s}\n");
  EXPECT_EQ(error_of(path), srdf +
                                ":3: <group_state name=\"s\"> <joint> \"l_knee_p\": value: "
                                "expected finite numbers separated by spaces, found \"nan\"");
}

// The joint values of <group_state name="STATE"> in the SRDF text, read with a regular expression.
std::map<std::string, std::string> state_values(const std::string& srdf_path,
                                                const std::string& state) {
  std::ifstream in(srdf_path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const std::regex block("<group_state\\s+name=\"" + state + "\"[^>]*>([\\s\\S]*?)</group_state>");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(all, m, block)) << state;
  const std::string body = m[1].str();
  const std::regex joint("<joint\\s+name=\"([^\"]+)\"\\s+value=\"([^\"]+)\"");
  std::map<std::string, std::string> out;
  for (auto it = std::sregex_iterator(body.begin(), body.end(), joint);
       it != std::sregex_iterator(); ++it)
    out[(*it)[1].str()] = (*it)[2].str();
  return out;
}

TEST_F(SrdfState, TalosHalfSittingReproducesTheSrdfExactly) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const std::string srdf = test::shared_path("robots/talos/robots/talos_data/srdf/talos.srdf");
  const std::string assets = test::source_path("assets");
  const std::string env = assets + "/environments/flat_ground/flat_ground";
  const std::string path = write("talos.yaml",
                                 "format: stanceplan/scenario@1\n"
                                 "entities:\n"
                                 "  - name: talos\n"
                                 "    kind: floating\n"
                                 "    urdf: " +
                                     test::talos_urdf() + "\n    package_paths: [" +
                                     test::talos_package_dir() + "]\n    srdf: " + srdf +
                                     "\n    configuration: {srdf_state: half_sitting}\n"
                                     "  - name: env\n    kind: environment\n    urdf: " +
                                     env + ".urdf\n    surfaces: " + env +
                                     ".surfaces.yaml\n"
                                     "stances: {initial: [], goal: []}\n"
                                     "physics: {gravity: [0, 0, 0]}\n");
  const Scenario s = load_scenario(path);
  const std::map<std::string, std::string> expected = state_values(srdf, "half_sitting");
  ASSERT_EQ(expected.size(), 31u);  // root_joint and 30 joints
  const Eigen::VectorXd& q = s.initial_configuration;
  for (const auto& [name, value] : expected) {
    SCOPED_TRACE(name);
    std::istringstream numbers(value);
    std::vector<double> v;
    for (double x; numbers >> x;) v.push_back(x);
    if (name == "root_joint") {
      ASSERT_EQ(v.size(), 7u);
      EXPECT_EQ(q.segment<3>(0), Eigen::Vector3d(v[0], v[1], v[2]));
      EXPECT_EQ(q.segment<4>(3), Eigen::Vector4d(v[6], v[3], v[4], v[5]));  // w x y z
      continue;
    }
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(joint(s, q, name), v[0]);
  }
  // The joints the state leaves out (the two grippers) keep their neutral value.
  EXPECT_EQ(joint(s, q, "gripper_left_joint"), 0.0);
}

}  // namespace
}  // namespace stanceplan
