#include "planner/plan/plan_step.h"

namespace stanceplan {

PlanStep make_plan_step(const PostureRequest& request, const PostureResult& result, Stance stance,
                        std::string action, std::optional<Contact> changed) {
  PlanStep step;
  step.action = std::move(action);
  step.changed = changed;
  for (const ContactTask& t : request.contacts) step.contacts.push_back({t.contact, t.loaded});
  step.stance = std::move(stance);
  step.q = result.q;
  step.forces = result.forces;
  step.torques = result.torques;
  step.status = result.status;
  step.iterations = result.iterations;
  step.time_ms = result.time_ms;
  step.objective = result.objective;
  return step;
}

}  // namespace stanceplan
