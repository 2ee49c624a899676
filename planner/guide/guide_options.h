#pragma once
// Settings of the computed guide path (docs/METHOD.md section 3, "The guide computed"): the seed,
// the budget of the path planner, the clearance and reach of its validity rule, and the spacing of
// the milestones it leaves for the search.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace stanceplan {

struct GuideOptions {
  std::uint32_t seed = 1;  // the path planner's samples (same seed, same guide)
  // The path planner's budget, per leg of the path: the state-validity checks it makes (a motion
  // checked every 2 cm counts each state it checks). No path within it: GuideStatus::NoPath.
  // Counted, never timed, so that the same scenario, options and seed give the same guide on any
  // machine (a wall-clock budget of 5 s gave the desk a guide in Release and none under ASan).
  // No wall-clock limit besides: the checks bound the time, and a clock would decide on a slow
  // machine. The scenarios' legs take at most 30277 checks (the desk, seed 1, 0.7 s in Release;
  // 38642 over seeds 1-12); a leg with no path spends it all (behind_wall: 6 s in Release).
  int max_checks = 200000;
  // Clearance (m) every checked collision pair keeps along the path: the guide stays off the
  // obstacles by more than the solver's margin, so that the postures near it are easy to solve.
  double clearance = 0.01;
  // RBPRM's reachability condition, simplified: a floating robot under gravity always has a
  // contact-capable surface within this distance (m) of a surface it may touch.
  double reach = 0.45;
  // Largest tilt (rad) of a floating robot's trunk from its initial roll and pitch while sampled
  // (objects turn freely).
  double max_tilt = 0.3;
  // Base travel (m) between two milestones: a few steps of the search.
  double spacing = 0.3;
  // The contact pairs the search may offer (search.contact_pairs): the validity rule's supports.
  // Empty: every pair of surfaces of different entities.
  std::vector<std::pair<std::string, std::string>> contact_pairs;
};

}  // namespace stanceplan
