#pragma once
// A plan step from the solve that produced it (docs/PLAN_FORMAT.md step semantics): the request's
// contacts are the touched ones, with their loaded flags; forces, torques and solver figures come
// from the result.
#include <optional>
#include <string>

#include "planner/plan/plan.h"
#include "planner/solver/posture_request.h"

namespace stanceplan {

PlanStep make_plan_step(const PostureRequest& request, const PostureResult& result, Stance stance,
                        std::string action, std::optional<Contact> changed);

}  // namespace stanceplan
