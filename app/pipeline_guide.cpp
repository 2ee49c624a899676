// The computed guide (app/pipeline.h): a guide for a scenario without one, read into it as its
// `guide:` section would be, and its strip.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>

#include "app/pipeline.h"
#include "planner/io/guide_writer.h"
#include "render/image/png_io.h"

namespace stanceplan::app {

std::string computed_guide_text(const Scenario& scenario, const ComputedGuide& guide) {
  char header[160];
  std::snprintf(header, sizeof header,
                "computed by stanceplan guide (seed %u): %zu milestones every %.2f m of base "
                "travel at most",
                unsigned(scenario.guide.seed), guide.milestones.size(), scenario.guide.spacing);
  std::vector<std::string> comment{header};
  if (!guide.phases.last.empty()) {
    std::string pairs;
    for (const auto& [s1, s2] : guide.phases.last)
      pairs += (pairs.empty() ? "[" : ", [") + s1 + ", " + s2 + "]";
    comment.push_back("offered last (search.last_contacts, unless the file states some): [" +
                      pairs +
                      "]: they carry less than half the weight of the goal's heaviest "
                      "new contact");
  }
  return guide_section(scenario.scene.system, guide.milestones, comment);
}

void print_guide_stats(const ComputedGuide& guide, std::ostream& out) {
  // Each leg's validity checks, "812+1290": the planner's effort against its budget per leg
  // (search.guide_max_checks), the same on any machine.
  std::string checks;
  for (const std::int64_t c : guide.leg_checks) {
    if (!checks.empty()) checks += '+';
    checks += std::to_string(c);
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "stats: guide %.3f s (goal posture %.3f s, path %.3f s: %s validity checks, %d "
                "waypoints, %zu after shortcuts, %d collision pairs checked), %zu milestones\n",
                guide.time_s, guide.posture_time_s, guide.path_time_s,
                checks.empty() ? "0" : checks.c_str(), guide.raw_waypoints, guide.path.size(),
                guide.checked_pairs, guide.milestones.size());
  out << line;
  if (!guide.approach_note.empty()) out << "stats: guide: " << guide.approach_note << "\n";
  if (guide.approach_milestones > 0)
    out << "stats: guide: " << guide.approach_milestones << " milestones approach "
        << (guide.stages > 0 ? "the crouch's" : "the goal's")
        << " footholds in the initial posture (" << guide.approach_back_off
        << " m short of them)\n";
  if (guide.stages > 0)
    out << "stats: guide: the last " << guide.stages << " milestones change the posture in stages ("
        << guide.stage_solves << " posture solves)\n";
  if (guide.completed_posture_change)
    out << "stats: guide: the written guide states no joints: its posture change completed, the "
           "approach's last milestone and "
        << guide.stages - 1 << " stages inserted before its last milestone, which gets the last "
        << "stage's heading and joints\n";
  if (guide.hand_over_milestone > 0)
    out << "stats: guide: milestone " << guide.hand_over_milestone
        << " hands the object over (both carriers hold it; " << guide.hand_over_solves
        << " grasps tried)\n";
  if (!guide.hand_over_note.empty()) out << "stats: guide: " << guide.hand_over_note << "\n";
}

std::string milestone_offer(const Scenario& scenario, const ComputedGuide& guide, size_t k) {
  const auto pairs = [](const std::vector<std::pair<std::string, std::string>>& list) {
    std::string out;
    for (const auto& [s1, s2] : list) out += (out.empty() ? "" : ", ") + s1 + " on " + s2;
    return out;
  };
  if (!guide.milestones[k].contacts.empty())
    return "walks on " + pairs(guide.milestones[k].contacts);
  std::string out = scenario.search.contact_pairs.empty()
                        ? "offers every contact"
                        : "offers " + pairs(scenario.search.contact_pairs);
  if (!scenario.search.last_contacts.empty())
    out += "; last: " + pairs(scenario.search.last_contacts);
  return out;
}

void write_guide_strip(const Scenario& scenario, const ComputedGuide& guide,
                       const std::string& path, std::ostream& out, std::ostream& err) {
  Plan plan;  // the initial configuration, then each milestone's configuration (no forces)
  PlanStep start;
  start.stance = scenario.stance(scenario.initial_stance);
  start.q = scenario.initial_configuration;
  plan.steps.push_back(start);
  for (size_t k = 0; k < guide.milestone_configurations.size(); ++k) {
    PlanStep step;
    const bool last = k + 1 == guide.milestone_configurations.size();
    step.action = "milestone " + std::to_string(k + 1) + (last ? " (goal posture)" : "") + "\n" +
                  milestone_offer(scenario, guide, k);
    if (last) step.stance = scenario.stance(scenario.goal_stance);
    step.q = guide.milestone_configurations[k];
    plan.steps.push_back(step);
  }
  const render::PlanView view = plan_view(scenario, plan);
  render::StripOptions strip;
  strip.title =
      view.name + "  —  computed guide, " + std::to_string(guide.milestones.size()) + " milestones";
  std::vector<std::string> warnings;
  const render::Image image =
      render::render_strip(view, strip, figure_options(view), nullptr, &warnings);
  for (const std::string& w : warnings) err << "stanceplan: warning: " << w << "\n";
  render::write_png(path, image);
  out << "render: guide strip of " << guide.milestones.size() << " milestones in " << path << "\n";
}

}  // namespace stanceplan::app
