#pragma once
// A partial guide completed (scenarios/README.md, "Partial guides"): a `guide:` section that
// states no milestone pose for a floating root (robot or object) that must move to reach the goal.
// Such a root "must move" when the goal contacts carry it (carried_configuration of
// goal_posture.h moves it by more than kMoves or turns it by more than kTurns); it is "stated"
// when any milestone states any entry of its root's pose. The computed guide's path (the whole
// problem's, guide_planner.h) gives each unstated root its pose at every written milestone: at
// milestone i of n, the pose at (i + 1) / n of that root's travel along the path (its position,
// and its orientation when it is an object that turns), as if the user had written it. What the
// file states is never changed.
#include <vector>

#include "planner/guide/guide_planner.h"
#include "planner/plan/problem.h"

namespace stanceplan {

inline constexpr double kMoves = 0.01;  // m
inline constexpr double kTurns = 0.01;  // rad

// The floating roots (entity indices) that must move and that no milestone states; empty when
// the problem has no milestones (a guide-free problem is not partial: it has no guide).
std::vector<int> unstated_moving_roots(const Problem& problem);

// Writes the computed path's poses of `roots` into every milestone of `problem` (and its masks).
// `guide` must be computed (status Computed) for this problem.
void complete_milestones(Problem& problem, const ComputedGuide& guide,
                         const std::vector<int>& roots);

}  // namespace stanceplan
