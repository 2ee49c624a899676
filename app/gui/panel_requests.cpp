// PanelApp's answers to what buttons, shortcuts and scripts ask for (panel_app_impl.h): the end of
// the search (the plan saved), exports, cancel, and after a failure or a cancel: run again, view
// the closest stance, export the partial plan.
#include <filesystem>
#include <ostream>
#include <sstream>

#include "app/exit_codes.h"
#include "app/gui/panel_app_impl.h"
#include "app/gui/panel_exports.h"
#include "app/gui/tree_section.h"
#include "app/pipeline.h"
#include "app/plan_output.h"

namespace stanceplan::app::panel_detail {

using namespace gui;

void PanelApp::on_search_finished(std::ostream& out, std::ostream& err) {
  const SearchResult& result = *mirror_.result();
  search_elapsed_s_ = result.wall_time_s;
  if (result.status != PlanStatus::Found || result.plan.steps.empty()) {
    state_.messages.push_back(std::string("no plan (") + to_string(result.status) +
                              "): Run again (R), view the closest stance, or export the "
                              "partial plan");
    return;
  }
  plan_ = std::make_shared<const Plan>(result.plan);
  const ViewSource was = state_.source;
  show_plan_step(state_, static_cast<int>(result.plan.steps.size()) - 1);
  if (was != ViewSource::Latest) state_.source = was;
  try {
    std::filesystem::create_directories(options_.out_dir);
    const std::string path = (std::filesystem::path(options_.out_dir) / "plan.json").string();
    std::ostringstream why;
    if (write_certified_plan(result.plan, scenario_, path, false, why) != kExitSuccess) {
      state_.messages.push_back("error: plan found but not saved: " + why.str());
      err << why.str();
      return;
    }
    state_.messages.push_back("plan found: " + std::to_string(result.plan.steps.size()) +
                              " steps, certified, saved " + path);
    out << "panel: " << state_.messages.back() << "\n";
    if (options_.motion && result.plan.steps.size() > 1) {
      motion_ = std::make_unique<MotionSession>(scenario_.scene, scenario_.solver, MotionOptions{},
                                                result.plan);
      motion_->start();
      state_.messages.push_back("computing the motion between the steps\u2026");
    }
  } catch (const std::exception& e) {
    state_.messages.push_back(std::string("error: ") + e.what());
    err << "stanceplan: error: " << e.what() << "\n";
  }
}

// Takes the motions computed since the last turn (the timeline plays them at once).
void PanelApp::sync_motion(std::ostream& out, std::ostream& err) {
  if (!motion_) return;
  const MotionProgress progress = motion_->progress();
  const bool finishing = progress.finished && !motion_handled_;
  if (progress.steps_done == motion_steps_shown_ && !finishing) return;
  plan_ = std::make_shared<const Plan>(motion_->plan());
  motion_steps_shown_ = progress.steps_done;
  if (finishing) {
    motion_handled_ = true;
    on_motion_finished(progress, out, err);
  }
}

// Every step tried: the plan is saved again with its motion (plan@2), certified sample by sample.
void PanelApp::on_motion_finished(const MotionProgress& progress, std::ostream& out,
                                  std::ostream& err) {
  if (progress.cancelled) return;
  const int motions = static_cast<int>(plan_->steps.size()) - 1;
  std::string moved = "motion: " + std::to_string(motions - progress.steps_failed) + " of " +
                      std::to_string(motions) + " steps moved";
  if (progress.steps_failed > 0)
    moved += " (first failure, kept without motion: " + progress.first_failure + ")";
  const std::string path = (std::filesystem::path(options_.out_dir) / "plan.json").string();
  std::ostringstream why;
  if (write_certified_plan(*plan_, scenario_, path, false, why) != kExitSuccess) {
    state_.messages.push_back("error: " + moved + ", not saved: " + why.str());
    err << why.str();
    return;
  }
  state_.messages.push_back(moved + ", certified, saved " + path);
  out << "panel: " << state_.messages.back() << "\n";
}

void PanelApp::carry_out_requests(long shown, const Rect& area) {
  if (state_.reset_camera) camera_ = framed_;
  state_.reset_camera = false;
  if (state_.cancel_search) session_->cancel();
  state_.cancel_search = false;
  carry_out_exports(shown, area);
  carry_out_failure_requests();
}

void PanelApp::carry_out_exports(long shown, const Rect& area) {
  const std::filesystem::path dir(options_.out_dir);
  if (state_.export_view && shown >= 0) {
    std::filesystem::create_directories(dir);
    const std::string name =
        state_.source == ViewSource::PlanStep
            ? "view_step_" + std::to_string(state_.plan_step) + ".png"
            : "view_event_" + std::to_string(mirror_.events()[shown].number) + ".png";
    view_.post(export_view_job(scenario_.scene, view_request(shown, area), meshes_,
                               (dir / name).string()));
    state_.messages.push_back("exporting " + (dir / name).string() + "\u2026");
  }
  state_.export_view = false;
  if (state_.export_strip && plan_) {
    std::filesystem::create_directories(dir);
    view_.post(export_strip_job(scenario_, plan_, meshes_, (dir / "strip.png").string()));
    state_.messages.push_back("exporting " + (dir / "strip.png").string() + "\u2026");
  }
  state_.export_strip = false;
}

// What the panel offers once a search ended without a plan.
void PanelApp::carry_out_failure_requests() {
  const bool failed = mirror_.finished() && !plan_;
  if (state_.show_closest && failed && mirror_.result()->closest_node >= 0)
    select_node(state_, mirror_.result()->closest_node);
  state_.show_closest = false;
  if (state_.export_partial && failed) {
    std::filesystem::create_directories(options_.out_dir);
    const std::string path =
        (std::filesystem::path(options_.out_dir) / "partial_plan.json").string();
    std::ostringstream said;
    const bool written = write_partial_plan(*mirror_.result(), scenario_, path, said);
    state_.messages.push_back(written ? "partial plan (to the closest stance) saved " + path
                                      : "no partial plan saved: " + said.str());
  }
  state_.export_partial = false;
  if (state_.rerun && mirror_.finished()) rerun();
  state_.rerun = false;
}

// A new search from the start in the same session (same solver processes and gate): the panel
// forgets the old one's events, tree, plan and selection; the camera and speed limit stay.
void PanelApp::rerun() {
  motion_.reset();  // joined before the search may fork again (fork_gate.h)
  motion_steps_shown_ = 0;
  motion_handled_ = false;
  session_->restart();
  driver_.restarted();
  mirror_ = SessionMirror();
  plan_.reset();
  finish_handled_ = false;
  search_start_ = Clock::now();
  search_elapsed_s_ = 0.0;
  last_view_key_.clear();
  state_.source = ViewSource::Latest;
  state_.selected_node = -1;
  state_.selected_event = -1;
  state_.plan_step = 0;
  state_.step_fraction = 0.0;
  state_.playing = false;
  state_.messages.push_back("search started again");
}

}  // namespace stanceplan::app::panel_detail
