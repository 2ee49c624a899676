#pragma once
// The computed guide path (docs/METHOD.md section 3, "The guide computed"): the paper's
// preprocessing step, a collision-free path from the initial to a goal configuration, sampled into
// the milestones the search follows. Three stages, each named when it fails:
//   goal posture: the IK-statics solver on the goal stance (goal_posture.h);
//   path:         RRT-Connect in the guide space (guide_space.h, ompl_path.h) under the validity
//                 rule of guide_validity.h, then shortcuts;
//   milestones:   points every GuideOptions::spacing of base travel (guide_milestones.h).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "planner/guide/contact_phases.h"
#include "planner/guide/guide_milestones.h"
#include "planner/guide/guide_options.h"
#include "planner/plan/problem.h"

namespace stanceplan {

enum class GuideStatus { Computed, NoGoalPosture, NoPath };
const char* to_string(GuideStatus status);

struct ComputedGuide {
  GuideStatus status = GuideStatus::NoPath;
  // When not computed: the stage that failed and why, e.g. "guide: goal posture: no posture for
  // the goal stance: Infeasible (...)" or "guide: path: no collision-free path ... within 200000
  // validity checks ...".
  std::string message;
  Eigen::VectorXd q_goal;                                 // the goal posture (when solved)
  std::vector<Eigen::VectorXd> path;                      // configurations at the path's waypoints
  std::vector<Eigen::VectorXd> milestone_configurations;  // configurations at the milestones
  std::vector<GuideMilestone> milestones;                 // what a scenario's guide: section states
  // The order of the goal's new contacts (contact_phases.h): `phases.last` are offered last.
  ContactPhases phases;
  // The first milestones that walk to the approach configuration (approach.h), 0 without one.
  int approach_milestones = 0;
  double approach_back_off = 0.0;  // m: the approach's feet short of the goal's footholds
  std::string approach_note;       // why a posture change has no approach, "" otherwise
  // The posture change's stages after the approach (posture_stages.h), 0 without; their solves.
  int stages = 0;
  int stage_solves = 0;
  // A carried object handed from one robot to another (hand_over.h): the milestone (counted from
  // 1) where both hold it, 0 without one; why a needed one was not found.
  int hand_over_milestone = 0;
  int hand_over_solves = 0;
  std::string hand_over_note;
  // When it completes a partial guide (partial_guide.h): the roots it gave poses to, and whether
  // it gave the guide its posture change (complete_posture_change).
  std::vector<int> completed;
  bool completed_posture_change = false;
  int raw_waypoints = 0;  // the planner's path before the shortcuts
  int checked_pairs = 0;  // collision pairs the validity rule checks
  // Each leg's state-validity checks in the path planner (GuideOptions::max_checks each), in the
  // order planned: the same for the same inputs on any machine, unlike the times below.
  std::vector<std::int64_t> leg_checks;
  double posture_time_s = 0.0, path_time_s = 0.0, time_s = 0.0;
};

ComputedGuide compute_guide(const Problem& problem, const GuideOptions& options);

}  // namespace stanceplan
