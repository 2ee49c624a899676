#pragma once
// The order in which the goal's new contacts are taken (docs/METHOD.md section 3, "The guide
// computed"): the supports that carry the body's weight in the goal posture before the ones that
// only steady it. Sitting down at a desk, the thighs on the seat carry most of the weight and the
// forearms on the desk little: a forearm put down first holds the trunk where the thighs cannot
// reach the seat (the guide-free desk found no plan in 25 s that way). Decided by the goal
// posture's own force distribution (the IK-statics solve of goal_posture.h), not by a person.
#include <string>
#include <utility>
#include <vector>

#include "planner/plan/problem.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

struct ContactPhases {
  // Per goal contact (the order of Problem::goal_stance): its share of the weight carried in the
  // goal posture (the vertical component of its forces over the sum of all contacts').
  std::vector<double> shares;
  // Per goal contact: whether the initial stance has it already.
  std::vector<bool> initial;
  // The goal's new contacts that only steady the body: each carries less than kSteadyingShare of
  // the largest share among the new contacts. Their surfaces as "entity/surface" pairs, in the
  // form of search.last_contacts (offered only once every other goal contact is in).
  std::vector<std::pair<std::string, std::string>> last;
  static constexpr double kSteadyingShare = 0.5;
};

// `goal` is the solve of problem.loaded_request(problem.goal_stance, ...): its forces are indexed
// by goal contact.
ContactPhases order_goal_contacts(const Problem& problem, const PostureResult& goal);

}  // namespace stanceplan
