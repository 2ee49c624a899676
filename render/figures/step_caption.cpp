#include "render/figures/step_caption.h"

#include <cctype>
#include <map>
#include <vector>

namespace stanceplan::render {
namespace {

// The surface's own name, or "entity/name" when another entity has a surface of that name (two
// arms with a pad_l each).
std::string surface_name(const Scene& scene, SurfaceRef ref) {
  const std::string& name = scene.surfaces.get(ref).name;
  for (int e = 0; e < scene.surfaces.num_entities(); ++e) {
    if (e == ref.entity) continue;
    for (const Surface& other : scene.surfaces.of(e))
      if (other.name == name) return scene.system.entity(ref.entity).name + "/" + name;
  }
  return name;
}

}  // namespace

std::string stance_summary(const Scene& scene, const Stance& stance) {
  if (stance.empty()) return "no contact";
  // Keep the order in which s2 surfaces first appear.
  std::vector<SurfaceRef> order;
  std::map<SurfaceRef, std::vector<std::string>> by_s2;
  for (const Contact& c : stance.contacts()) {
    if (!by_s2.contains(c.s2)) order.push_back(c.s2);
    by_s2[c.s2].push_back(surface_name(scene, c.s1));
  }
  std::string out;
  for (const SurfaceRef& s2 : order) {
    if (!out.empty()) out += "; ";
    const std::vector<std::string>& s1s = by_s2[s2];
    for (size_t i = 0; i < s1s.size(); ++i) out += (i > 0 ? ", " : "") + s1s[i];
    out += " on " + surface_name(scene, s2);
  }
  return out;
}

std::string step_action(const Scene& scene, const PlanStep& step) {
  // A figure of something that is not a plan step (a computed guide's milestone) labels itself.
  if (!step.changed && step.action != "initial" && step.action != "add" && step.action != "remove")
    return step.action.substr(0, step.action.find('\n'));
  if (step.action == "initial" || !step.changed) return "initial stance";
  const std::string s1 = surface_name(scene, step.changed->s1),
                    s2 = surface_name(scene, step.changed->s2);
  if (step.action == "add") return "add " + s1 + " on " + s2;
  if (step.action == "remove") return "remove " + s1 + " from " + s2;
  return step.action + " " + s1 + " / " + s2;
}

std::string step_detail(const Scene& scene, const PlanStep& step) {
  const size_t newline = step.action.find('\n');
  if (!step.changed && newline != std::string::npos) return step.action.substr(newline + 1);
  return stance_summary(scene, step.stance);
}

std::string step_caption(const PlanView& plan, int step) {
  // Steps are numbered as in the plan file (0 = the initial stance); "of N" counts transitions.
  const PlanStep& s = plan.plan.steps.at(step);
  const int last = static_cast<int>(plan.plan.steps.size()) - 1;
  const std::string action = step_action(plan.scene, s);
  std::string caption;
  if (last == 0) {
    caption = action;
    caption[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(caption[0])));
  } else {
    caption.append("Step ")
        .append(std::to_string(step))
        .append(" of ")
        .append(std::to_string(last));
    caption.append("  \u00b7  ").append(action);
  }
  // The last iterate of a failed solve (`posture --out` without a posture) says so first.
  if (s.status != PostureStatus::Solved)
    caption.insert(0, std::string("FAILED (") + to_string(s.status) + ", not a posture)  \u00b7  ");
  // A figure that is not a plan step (a computed guide's milestone) says in its own label what it
  // offers, not "no contact".
  if (!s.changed && s.action.find('\n') != std::string::npos)
    caption.append("\n").append(step_detail(plan.scene, s));
  else
    caption.append("\nstance: ").append(stance_summary(plan.scene, s.stance));
  return caption;
}

std::string plan_title(const PlanView& plan) {
  return plan.name;
}

}  // namespace stanceplan::render
