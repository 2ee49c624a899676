#pragma once
// A position on a plan's timeline, as the figures play it (the GIF, the panel's timeline): the
// position p runs over [0, steps - 1]; step i sits at p = i and the motion into step i + 1 fills
// (i, i + 1), its samples evenly spaced whatever their number (a steady speed of one step per
// unit).
#include "planner/plan/plan.h"

namespace stanceplan {

// What is shown at a position: a step's own posture (sample < 0), or sample `sample` of the motion
// into `step` (PlanStep::motion->samples).
struct TimelinePoint {
  int step = 0;
  int sample = -1;
  bool operator==(const TimelinePoint& o) const { return step == o.step && sample == o.sample; }
};

// Whether any step holds motion samples (else the timeline is the steps alone).
bool has_motion(const Plan& plan);

// The point at `position` (clamped to the timeline). The fraction f of the way from step i to i + 1
// picks the nearest of the n + 2 evenly spaced points [step i, samples 0..n-1, step i + 1]. Without
// samples into step i + 1 (no motion, or a failed one) step i is held until p reaches i + 1.
TimelinePoint timeline_point(const Plan& plan, double position);

}  // namespace stanceplan
