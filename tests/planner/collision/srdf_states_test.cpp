// SRDF group states (<group_state><joint name value/></group_state>) and floating virtual joints as
// the SRDF reader returns them, and its faults with file and line.
#include <gtest/gtest.h>

#include "planner/collision/srdf.h"
#include "planner/util/input_error.h"
#include "tests/support/input_errors.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using test::error_of;

TEST(SrdfStates, StatesJointsValuesAndLinesInFileOrder) {
  const SrdfStates srdf = parse_srdf_states(R"(<robot name="r">
  <virtual_joint name="world_joint" type="floating" parent_frame="world" child_link="base"/>
  <virtual_joint name="rail" type="planar" parent_frame="world" child_link="base"/>
  <group_state name="home" group="arm">
    <joint name="j1" value="0.25"/>
    <joint name="world_joint" value=" 1 2 3  0 0 0 1 "/>
  </group_state>
  <disable_collisions link1="a" link2="b" reason="Never"/>
  <group_state name="open" group="hand"><joint name="finger" value="-1e-3"/></group_state>
</robot>)",
                                            "r.srdf");
  ASSERT_EQ(srdf.states.size(), 2u);
  EXPECT_EQ(srdf.states[0].name, "home");
  EXPECT_EQ(srdf.states[0].group, "arm");
  EXPECT_EQ(srdf.states[0].line, 4);
  ASSERT_EQ(srdf.states[0].joints.size(), 2u);
  EXPECT_EQ(srdf.states[0].joints[0].joint, "j1");
  EXPECT_EQ(srdf.states[0].joints[0].values, std::vector<double>{0.25});
  EXPECT_EQ(srdf.states[0].joints[0].line, 5);
  EXPECT_EQ(srdf.states[0].joints[1].values, (std::vector<double>{1, 2, 3, 0, 0, 0, 1}));
  EXPECT_EQ(srdf.states[1].joints[0].values, std::vector<double>{-1e-3});
  EXPECT_EQ(srdf.floating_joints, std::vector<std::string>{"world_joint"});  // not the planar one
  // The disabled pairs are read from the same text as before.
  EXPECT_EQ(parse_srdf_disabled_collisions("<robot><disable_collisions link1=\"a\" link2=\"b\"/>"
                                           "</robot>")
                .size(),
            1u);
}

TEST(SrdfStates, AJointWithoutValue) {
  EXPECT_EQ(error_of([] {
              parse_srdf_states(
                  "<robot>\n<group_state name=\"s\" group=\"g\">\n<joint name=\"j\"/>\n"
                  "</group_state></robot>",
                  "x.srdf");
            }),
            "x.srdf:3: <group_state name=\"s\"> <joint> \"j\": expected attribute value");
}

TEST(SrdfStates, AStateWithoutName) {
  EXPECT_EQ(
      error_of([] { parse_srdf_states("<robot>\n<group_state group=\"g\"/></robot>", "x.srdf"); }),
      "x.srdf:2: <group_state>: expected attribute name");
}

TEST(SrdfStates, AValueThatIsNotNumbers) {
  EXPECT_EQ(error_of([] {
              parse_srdf_states(
                  "<robot><group_state name=\"s\" group=\"g\"><joint name=\"j\" value=\"1 two\"/>"
                  "</group_state></robot>",
                  "x.srdf");
            }),
            "x.srdf:1: <group_state name=\"s\"> <joint> \"j\": value: expected finite numbers "
            "separated by spaces, found \"1 two\"");
}

TEST(SrdfStates, TheSharedRobotsStates) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const SrdfStates talos =
      load_srdf_states(test::shared_path("robots/talos/robots/talos_data/srdf/talos.srdf"));
  ASSERT_EQ(talos.states.size(), 1u);
  EXPECT_EQ(talos.states[0].name, "half_sitting");
  EXPECT_EQ(talos.states[0].joints.size(), 31u);
  EXPECT_EQ(talos.states[0].joints[0].values,
            (std::vector<double>{0, 0, 1.01927, 0, 0, 0, 1}));  // "0. 0. 1.01927 0. 0. 0. 1."
  const SrdfStates panda =
      load_srdf_states(test::shared_path("robots/panda/robots/panda_description/srdf/panda.srdf"));
  ASSERT_EQ(panda.states.size(), 1u);
  EXPECT_EQ(panda.states[0].name, "default");
  EXPECT_EQ(panda.states[0].joints.size(), 8u);
}

}  // namespace
}  // namespace stanceplan
