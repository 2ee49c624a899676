#pragma once
// Words for a plan's steps: the caption of a step image, the short label under a strip panel and
// a stance summary ("l_sole, r_sole on floor; r_hand on table").
#include <string>

#include "planner/contact/contact.h"
#include "render/figures/plan_view.h"

namespace stanceplan::render {

// "l_sole, r_sole on floor; r_hand on table" (contacts grouped by their s2 surface).
std::string stance_summary(const Scene& scene, const Stance& stance);
// "initial stance", "add r_hand on table", "remove l_sole from floor".
std::string step_action(const Scene& scene, const PlanStep& step);
// The line under a step's action: its stance; for a labelled figure that is not a plan step (a
// computed guide's milestone, whose action is "LABEL\nDETAIL"), its detail.
std::string step_detail(const Scene& scene, const PlanStep& step);
// Two lines: "Step 3 of 6 · add r_hand on table" (steps numbered as in the plan, 0 = initial)
// and "stance: ...". A one-step plan says "Initial stance".
std::string step_caption(const PlanView& plan, int step);
// The plan's name for titles (PlanView::name).
std::string plan_title(const PlanView& plan);

}  // namespace stanceplan::render
