#pragma once
// The parts of an SRDF file (MoveIt's Semantic Robot Description Format) the planner uses: the
// link pairs whose collisions are disabled, <disable_collisions link1="" link2="" reason=""/>, for
// the collision model; and the named postures, <group_state name="" group=""><joint name=""
// value=""/></group_state>, that scenarios start from (`srdf_state`, scenarios/README.md).
#include <string>
#include <vector>

namespace stanceplan {

struct DisabledCollision {
  std::string link1;
  std::string link2;
  std::string reason;  // "Adjacent", "Never", ... (informative only; may be empty)
};

// Throws InputError naming the file (and the line when known) on a missing file, malformed XML,
// a root element other than <robot>, or a <disable_collisions> without link1/link2.
std::vector<DisabledCollision> load_srdf_disabled_collisions(const std::string& path);
// Same, from XML text; display_name stands for the file name in messages.
std::vector<DisabledCollision> parse_srdf_disabled_collisions(
    const std::string& xml, const std::string& display_name = "<string>");

// One joint of a group state: one value for a revolute or prismatic joint (rad or m), several
// for a multi-dof joint (a floating base: x y z qx qy qz qw, as MoveIt and Pinocchio write it).
struct SrdfJointValue {
  std::string joint;
  std::vector<double> values;
  int line = 0;  // of its <joint> element in the file
};

struct SrdfGroupState {
  std::string name;
  std::string group;
  int line = 0;
  std::vector<SrdfJointValue> joints;  // in file order
};

struct SrdfStates {
  std::vector<SrdfGroupState> states;  // in file order; a name may recur for other groups
  // Names of the <virtual_joint type="floating"> elements: the robot's free base.
  std::vector<std::string> floating_joints;
};

// Throws InputError naming the file and line on a missing file, malformed XML, a root other than
// <robot>, a <group_state> or <joint> without its name, a <joint> without a value, or a value that
// is not a list of finite numbers.
SrdfStates load_srdf_states(const std::string& path);
SrdfStates parse_srdf_states(const std::string& xml, const std::string& display_name = "<string>");

}  // namespace stanceplan
