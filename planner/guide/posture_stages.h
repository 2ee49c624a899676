#pragma once
// The posture change in stages (docs/METHOD.md section 3, "The guide computed"): where a robot
// walks to its goal standing (approach.h) and changes posture there (sits down), one milestone at
// the goal posture leaves the search to find, by itself, the order in which the new contacts land
// and which kept contact must be lifted meanwhile (the guide-free desk found none in 400 nodes).
// Each stage is a posture the IK-statics solver (section 4) finds for a sub-stance of the goal,
// with the limbs that only reach for the contacts offered last (contact_phases.h: the forearms)
// in their initial joints until the goal stage:
//   crouch:  the kept contacts only (feet), where balance puts them, near the goal posture: under
//            the body, not stretched under the desk as the goal posture's are; the robot walks to
//            these footholds (approach.h);
//   seated:  every goal contact but the last ones, solved from the crouch;
//   one limb free (before seated): the seated placements but for the last-ordered heavy contact
//            (a thigh) and the kept contacts on its limb: each leg below the thigh has three pitch
//            joints, and a foot and a thigh both placed pin them (the second thigh with both feet
//            down lands nowhere), so that leg's foot is lifted while the other thigh lands;
//   goal:    the last contacts added to the seated placements, towards the goal posture.
// The milestones state each stage's joints and offer its contacts (the crouch the feet only).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "planner/guide/contact_phases.h"
#include "planner/plan/problem.h"

namespace stanceplan {

struct PostureStage {
  std::string name;   // "crouch", "one limb free", "seated", "goal"
  Eigen::VectorXd q;  // the solved posture
  // The contact pairs offered while it is the target ("entity/surface"); empty: every pair.
  std::vector<std::pair<std::string, std::string>> offered;
};

// The stages to the goal stance, near `q_goal` (the goal posture; `phases` its contact order).
// Empty when the crouch or the seated stage cannot be solved, or the goal keeps no contact of the
// initial stance or adds none that carries weight.
std::vector<PostureStage> posture_stages(const Problem& problem, const Eigen::VectorXd& q_goal,
                                         const ContactPhases& phases, int* solves = nullptr);

}  // namespace stanceplan
