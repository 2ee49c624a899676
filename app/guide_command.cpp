#include "app/guide_command.h"

#include <iomanip>
#include <ostream>

#include "app/exit_codes.h"
#include "app/model_warnings.h"
#include "app/pipeline.h"
#include "planner/util/atomic_file.h"

namespace stanceplan::app {

int run_guide(const GuideCommandOptions& options, std::ostream& out, std::ostream& err) {
  Scenario scenario = load_scenario(options.scenario);
  print_model_warnings(scenario.scene, err);
  if (options.seed) scenario.guide.seed = *options.seed;
  if (scenario.has_guide)
    err << "stanceplan: " << options.scenario
        << " has a guide: section of its own (plan uses it); computing one all the same\n";
  scenario.has_guide = false;
  const std::optional<ComputedGuide> guide = complete_scenario_guide(scenario);
  if (options.stats) print_guide_stats(*guide, out);
  if (guide->status != GuideStatus::Computed) {
    err << "stanceplan: " << guide->message << "\n";
    return kExitFailed;
  }
  const std::string text = computed_guide_text(scenario, *guide);
  if (options.out.empty()) {
    out << text;
  } else {
    write_file_atomically(options.out, text);
    out << "wrote " << options.out << "\n";
  }
  if (!options.strip.empty()) write_guide_strip(scenario, *guide, options.strip, out, err);
  err << "computed the guide in " << std::fixed << std::setprecision(3) << guide->time_s
      << " s: " << guide->milestones.size() << " milestones\n";
  return kExitSuccess;
}

}  // namespace stanceplan::app
