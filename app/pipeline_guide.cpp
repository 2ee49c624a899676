// The computed guide (app/pipeline.h): a guide for a scenario without one, read into it as its
// `guide:` section would be, and its strip.
#include <chrono>
#include <cstdio>
#include <ostream>

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
  return guide_section(scenario.scene.system, guide.milestones, {header});
}

std::optional<ComputedGuide> complete_guide(Scenario& scenario) {
  if (scenario.has_guide) return std::nullopt;
  ComputedGuide guide = compute_guide(scenario, scenario.guide);
  if (guide.status == GuideStatus::Computed)
    read_guide_section(scenario, computed_guide_text(scenario, guide),
                       scenario.file + " (computed guide)");
  return guide;
}

void print_guide_stats(const ComputedGuide& guide, std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line,
                "stats: guide %.3f s (goal posture %.3f s, path %.3f s: %d waypoints, %zu after "
                "shortcuts, %d collision pairs checked), %zu milestones\n",
                guide.time_s, guide.posture_time_s, guide.path_time_s, guide.raw_waypoints,
                guide.path.size(), guide.checked_pairs, guide.milestones.size());
  out << line;
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
    step.action = "milestone " + std::to_string(k + 1) + (last ? " (goal posture)" : "");
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
