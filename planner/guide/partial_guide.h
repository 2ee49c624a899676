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
#include <optional>
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

// A partial guide also leaves out a posture change when no milestone states a joint of any robot:
// a coarse guide to a chair states where the waist goes, not how the robot sits down. Whether the
// goal is a posture change is the computed guide's to say (ComputedGuide::stages > 0: the goal
// stance keeps contacts of the initial one and adds some that carry weight, posture_stages.h).
bool states_no_joints(const Problem& problem);

// Completes such a guide with the computed one's posture change: before the last written
// milestone, the approach's last milestone (standing at the crouch's footholds, its heading
// stated) and the stages but the last (crouch, one limb free, seated: each its whole posture and
// its contacts); the last written milestone keeps what it states (the seated waist's position)
// and gets the last stage's heading and joints, which it leaves out. The milestones before stay as
// written. `guide` must be computed with stages (ComputedGuide::stages > 0).
void complete_posture_change(Problem& problem, const ComputedGuide& guide);

// A written guide completed as `stanceplan plan` completes it: the roots it leaves out
// (complete_milestones) and the posture change it leaves out (complete_posture_change: no joints
// stated, and the goal keeps a contact of the initial stance and adds one), from the guide
// computed for the whole problem. nullopt when there is nothing to complete: the written guide
// is used as it is (also when only a posture change was left out and the computed guide
// has none). A guide that fails while roots are left out is returned as it failed.
std::optional<ComputedGuide> complete_written_guide(Problem& problem, const GuideOptions& options);

}  // namespace stanceplan
