#include "app/gui/panel_app.h"

#include <imgui.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

#include "app/collision_matrix_note.h"
#include "app/exit_codes.h"
#include "app/gui/controls_section.h"
#include "app/gui/guide_overlay.h"
#include "app/gui/node_section.h"
#include "app/gui/panel_app_impl.h"
#include "app/gui/panel_script.h"
#include "app/gui/plan_bar_section.h"
#include "app/gui/plots_section.h"
#include "app/gui/tree_section.h"
#include "app/gui/ui_style.h"
#include "app/gui/view_section.h"
#include "app/interrupt_handler.h"
#include "app/live/event_record.h"
#include "app/model_warnings.h"
#include "app/pipeline.h"
#include "planner/util/fork_gate.h"
#include "render/figures/step_caption.h"
#include "render/image/png_io.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::app {
namespace panel_detail {

std::atomic<int> g_close_signal{0};

using namespace gui;

namespace {

constexpr double kFramePeriod =
    1.0 / 30.0;  // the loop turns (and redraws) at most 30 times a second
constexpr ImGuiWindowFlags kSideWindow = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The live view's look: the cheaper preview style (render_style.h), same colours as the PNGs.
render::RenderStyle live_style(const Scenario& scenario) {
  render::RenderStyle style = render::RenderStyle::preview();
  style.friction = scenario.solver.friction;
  return style;
}

// A sample of the motion into a step (`at.sample` >= 0): its configuration and forces on the
// stance of the step before, every contact loaded (as the GIF draws it), and a caption line.
void show_motion_sample(const Plan& plan, const TimelinePoint& at, ViewRequest& r) {
  if (at.sample < 0) return;
  const StepMotion& motion = *plan.steps[static_cast<size_t>(at.step)].motion;
  const MotionSample& sample = motion.samples[static_cast<size_t>(at.sample)];
  r.q = sample.q;
  r.forces = sample.forces;
  r.contacts.clear();
  for (const Contact& c : plan.steps[static_cast<size_t>(at.step - 1)].stance.contacts())
    r.contacts.push_back({c, true});
  r.caption += "\nmotion into step " + std::to_string(at.step) + ": sample " +
               std::to_string(at.sample + 1) + " of " + std::to_string(motion.samples.size());
}

// One framing for the whole search (so that consecutive pictures line up): the robots at the
// initial configuration and at every milestone, seen from three-quarter view.
render::Camera initial_camera(const Scenario& scenario, const render::RenderStyle& style,
                              render::MeshLibrary& meshes, double aspect) {
  const Scene& scene = scenario.scene;
  Eigen::AlignedBox3d box =
      render::assemble_frame(scene, scenario.initial_configuration, {}, {}, style, meshes).bounds();
  for (const Eigen::VectorXd& q : scenario.milestones)
    box.extend(render::assemble_frame(scene, q, {}, {}, style, meshes).bounds());
  if (box.isEmpty())
    box = render::assemble_frame(scene, scenario.initial_configuration, {}, {}, style, meshes)
              .bounds(true);
  return render::frame_box(box, render::View::ThreeQuarter, aspect, render::frame_margins(style));
}

}  // namespace
extern "C" void note_close_signal(int signal_number) {
  g_close_signal.store(signal_number);
}

// SIGINT / SIGTERM end the panel as closing its window does (the loop sees the flag within a
// frame period); the previous handlers come back when the panel ends.
class CloseOnSignal {
 public:
  CloseOnSignal() { g_close_signal = 0; }

 private:
  InterruptHandler handler_{note_close_signal};
};

PanelApp::PanelApp(const Scenario& scenario, const PanelOptions& options,
                   std::vector<ScriptAction> script)
    : scenario_(scenario),
      options_(options),
      // With motion, the search checks the motion of the plan it finds (lazy validation).
      session_(std::make_unique<PlanSession>(
          scenario, search_options_with_overrides(scenario, options),
          options.motion ? std::optional<MotionOptions>(MotionOptions{}) : std::nullopt)),
      window_(options.width, options.height, "stanceplan \u2014 " + scenario.name),
      meshes_(std::make_shared<render::MeshLibrary>()),
      style_(live_style(scenario)),
      view_(scenario.scene, style_, meshes_),
      texture_(window_.gl()),
      driver_(session_->gate(), options.start_paused),
      goal_stance_(scenario.stance(scenario.goal_stance)) {
  driver_.set_speed_limit(options.speed_limit);
  state_.speed_limit = static_cast<float>(options.speed_limit);
  state_.export_folder = options.out_dir;
  if (!script.empty()) script_.emplace(std::move(script));
  const PanelLayout layout =
      panel_layout(float(window_.framebuffer_width()), float(window_.framebuffer_height()));
  camera_ = OrbitCamera(
      initial_camera(scenario, style_, *meshes_, layout.view.w / std::max(layout.view.h, 1.0f)));
  framed_ = camera_;
  session_->start();
  search_start_ = Clock::now();
}

int PanelApp::run(std::ostream& out, std::ostream& err) {
  int frames = 0;                         // counted (see frames_after_search)
  Clock::time_point last = Clock::now();  // the last frame drawn
  Clock::time_point turn = last;          // the last loop turn
  while (!window_.should_close()) {
    // At most kFramePeriod between loop turns; input wakes the loop at once.
    window_.wait_events(std::max(kFramePeriod - ms_since(turn) / 1000.0, 0.0));
    const double turn_dt = ms_since(turn) / 1000.0;
    turn = Clock::now();
    if (const int signal_number = g_close_signal.exchange(0)) {
      out << "panel: " << (signal_number == SIGINT ? "SIGINT" : "SIGTERM")
          << " received: closing the window\n";
      window_.request_close();
      continue;
    }
    {
      const ForkGate::Pass pass;  // the search forks between turns (planner/util/fork_gate.h)
      pace(turn_dt, out, err);    // every turn, drawn or not: the speed limit needs no input
      advance_script(out, err);
    }
    if (!needs_frame()) continue;  // idle: nothing to redraw, no CPU taken from the search
    const Clock::time_point start = Clock::now();
    const double dt = std::chrono::duration<double>(start - last).count();
    last = start;
    // Scripted runs count their frames from the start, or from the end of the search.
    if (!options_.frames_after_search || mirror_.finished()) ++frames;
    const bool final_frame = options_.exit_after_frames > 0 && frames >= options_.exit_after_frames;
    draw_frame(dt, final_frame, out, err);
    frame_ms_.push_back(ms_since(start));  // the panel's own work: events, drawing, upload
    if (final_frame) window_.request_close();
  }
  const double stop_ms = stop_search();
  out << "panel: " << frame_ms_.size() << " frames, median frame " << std::fixed
      << std::setprecision(1) << median(frame_ms_) << " ms; 3-D view: " << view_.frames_rendered()
      << " images, median render " << view_.median_render_ms() << " ms; search stopped " << stop_ms
      << " ms after the window closed\n";
  return script_failed_ ? kExitFailed : kExitSuccess;
}

// Takes the search's new events and applies the run mode and speed limit to the step gate; at
// the end of the search, saves the plan (before a script's next action: it may move the timeline).
void PanelApp::pace(double dt_s, std::ostream& out, std::ostream& err) {
  const size_t before = mirror_.events().size();
  mirror_.sync(*session_);
  std::vector<SearchEventKind> arrived;
  for (size_t i = before; i < mirror_.events().size(); ++i)
    arrived.push_back(mirror_.events()[i].kind);
  driver_.update(arrived, dt_s);
  if (!mirror_.finished())
    search_elapsed_s_ = std::chrono::duration<double>(Clock::now() - search_start_).count();
  if (options_.select_node && mirror_.tree().node(*options_.select_node) != nullptr) {
    select_node(state_, *options_.select_node);
    options_.select_node.reset();
  }
  if (mirror_.finished() && !finish_handled_) {
    on_search_finished(out, err);
    finish_handled_ = true;
  }
  sync_motion(out, err);
}

// A frame is drawn when something changed: input, a search event, the end of the search, a new
// picture or message from the render thread, playback, scripted mouse moves or a screenshot; and
// a few more after that, for ImGui's hover and active states to settle. Runs with
// --exit-after-frames draw every turn (they count frames).
bool PanelApp::needs_frame() {
  const bool changed = options_.exit_after_frames > 0 || state_.playing ||
                       window_.input_events() != seen_input_ || view_.has_news() ||
                       mirror_.events().size() != drawn_events_ ||
                       mirror_.finished() != drawn_finished_ || !pointer_moves_.empty() ||
                       motion_steps_shown_ != drawn_motion_steps_ || !pending_screenshot_.empty() ||
                       state_.open_tab >= 0;
  seen_input_ = window_.input_events();
  drawn_events_ = mirror_.events().size();
  drawn_finished_ = mirror_.finished();
  drawn_motion_steps_ = motion_steps_shown_;
  if (changed) settle_frames_ = 3;
  if (settle_frames_ == 0) return false;
  --settle_frames_;
  return true;
}

void PanelApp::draw_frame(double dt_s, bool last, std::ostream& out, std::ostream& err) {
  const ForkGate::Pass pass;  // the search forks between frames (planner/util/fork_gate.h)
  std::optional<ScriptedPointer> pointer;
  if (!pointer_moves_.empty()) {
    pointer = pointer_moves_.front();
    pointer_moves_.pop_front();
  }
  window_.begin_frame(pointer);
  if (plan_) {
    advance_timeline(state_, static_cast<int>(plan_->steps.size()), dt_s);
    // A node selected on the plan moves the timeline to its step.
    if (state_.source == ViewSource::Node) {
      const std::vector<int> path = mirror_.tree().plan_path();
      const auto on_plan = std::find(path.begin(), path.end(), state_.selected_node);
      if (on_plan != path.end()) {
        state_.plan_step = static_cast<int>(on_plan - path.begin());
        state_.step_fraction = 0.0;
      }
    }
  }
  frame(last, out, err);
}

// The window closed: cancel the search (it stops between solver iterations) and join its thread;
// the motion's thread stops after the step it is computing.
double PanelApp::stop_search() {
  const Clock::time_point start = Clock::now();
  motion_.reset();
  session_.reset();
  return ms_since(start);
}

long PanelApp::shown_event() const {
  const SearchTree& tree = mirror_.tree();
  switch (state_.source) {
    case ViewSource::Latest:
      for (size_t i = mirror_.events().size(); i-- > 0;)
        if (mirror_.events()[i].q.size() > 0) return static_cast<long>(i);
      return -1;
    case ViewSource::Node:
      return tree.node(state_.selected_node)
                 ? static_cast<long>(tree.node(state_.selected_node)->event)
                 : -1;
    case ViewSource::Event:
      return state_.selected_event;
    case ViewSource::PlanStep: {  // a motion sample shows the event of the step it goes to
      const std::vector<int> path = tree.plan_path();
      const int step = timeline_at().step;
      if (step < 0 || step >= static_cast<int>(path.size())) return -1;
      return static_cast<long>(tree.node(path[step])->event);
    }
  }
  return -1;
}

TimelinePoint PanelApp::timeline_at() const {
  if (!plan_) return {state_.plan_step, -1};
  return timeline_point(*plan_, state_.plan_step + state_.step_fraction);
}

std::string PanelApp::shown_title(long shown) const {
  if (shown < 0) return "";
  const SearchEvent& e = mirror_.events()[shown];
  switch (state_.source) {
    case ViewSource::Latest:
      return "Newest: event " + std::to_string(e.number);
    case ViewSource::Node:
      return "Node " + std::to_string(state_.selected_node);
    case ViewSource::Event:
      return "Rejected candidate (event " + std::to_string(e.number) + ")";
    case ViewSource::PlanStep: {
      const TimelinePoint at = timeline_at();
      if (at.sample >= 0)
        return "Motion to plan step " + std::to_string(at.step) + ", sample " +
               std::to_string(at.sample + 1) + " (node " + std::to_string(e.node) + ")";
      return "Plan step " + std::to_string(at.step) + " (node " + std::to_string(e.node) + ")";
    }
  }
  return "";
}

// What the view shows: the event `shown`, or before the first event (a paused start) the
// scenario's initial configuration, which the search has not solved yet.
ViewRequest PanelApp::view_request(long shown, const Rect& area) const {
  ViewRequest r;
  if (shown >= 0) {
    const SearchEvent& e = mirror_.events()[shown];
    r.q = e.q;
    r.contacts = e.contacts;
    r.forces = e.forces;
    const int milestones = static_cast<int>(scenario_.milestones.size());
    const bool on_plan = state_.source == ViewSource::PlanStep && plan_;
    r.caption = on_plan
                    ? render::step_caption(app::plan_view(scenario_, *plan_), timeline_at().step)
                    : event_caption(scenario_.scene, e, milestones);
    if (on_plan) show_motion_sample(*plan_, timeline_at(), r);
    // The milestone the search aims at, as a ghost (not over the plan's steps).
    if (state_.source != ViewSource::PlanStep)
      if (const auto aimed = aimed_milestone(scenario_.milestones, e.milestone)) {
        r.ghost_q = aimed->q;
        r.caption += "\n" + aimed_caption(*aimed);
      }
  } else {
    r.q = scenario_.initial_configuration;
    r.caption =
        "Initial configuration, as the scenario states it\nnot solved yet: the search has "
        "published no event";
  }
  r.camera = camera_.camera();
  // The picture has the view's size in framebuffer pixels (larger than window units on HiDPI).
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  r.width = std::max(16, static_cast<int>(area.w * scale.x));
  r.height = std::max(16, static_cast<int>(area.h * scale.y));
  return r;
}

// Asks the render thread for a new picture when what is shown, the camera or the size changed;
// uploads the newest finished one. `wait`: block until the picture asked for is there.
void PanelApp::update_view(long shown, const Rect& area, bool wait) {
  ViewRequest request = view_request(shown, area);
  const render::Camera& c = request.camera;
  std::ostringstream key;
  const TimelinePoint at = timeline_at();
  key << shown << ' ' << int(state_.source) << ' ' << at.step << ' ' << at.sample << ' '
      << motion_steps_shown_ << ' ' << request.width << 'x' << request.height << ' '
      << c.eye.transpose() << ' ' << c.target.transpose();
  if (key.str() != last_view_key_) {
    last_view_key_ = key.str();
    last_view_id_ = view_.request(std::move(request));
  }
  if (wait && last_view_id_ > 0) view_.wait_for(last_view_id_, std::chrono::seconds(30));
  if (std::optional<ViewFrame> frame = view_.take()) texture_.upload(frame->image);
}

void PanelApp::frame(bool last, std::ostream& out, std::ostream& err) {
  const ImVec2 window = ImGui::GetIO().DisplaySize;  // ImGui's units: window coordinates
  const PanelLayout layout = panel_layout(window.x, window.y);
  const long shown = shown_event();
  // The tree keeps the newest node in sight while following, else the selection.
  const int focus = state_.source == ViewSource::Latest
                        ? static_cast<int>(mirror_.tree().nodes().size()) - 1
                    : state_.source == ViewSource::Node ? state_.selected_node
                    : shown >= 0                        ? mirror_.events()[shown].node
                                                        : state_.tree_focus;
  if (focus != state_.tree_focus) {
    state_.tree_focus = focus;
    state_.reveal_focus = true;
  }
  const std::string screenshot = last ? options_.screenshot : pending_screenshot_;
  update_view(shown, layout.view, !screenshot.empty());
  draw_windows(shown, layout);
  handle_shortcuts();
  carry_out_requests(shown, layout.view);
  for (std::string& m : view_.take_messages()) {
    if (m.rfind("error", 0) == 0) err << "stanceplan: " << m << "\n";
    state_.messages.push_back(std::move(m));
  }
  window_.end_frame(kWindowClear);
  if (!screenshot.empty()) {
    render::write_png(screenshot, window_.read_back_buffer());
    out << "panel: window saved to " << screenshot << "\n";
    pending_screenshot_.clear();
  }
  window_.present();
}

void PanelApp::draw_windows(long shown, const PanelLayout& layout) {
  draw_view_section(layout.view, texture_, camera_, state_);
  const int milestones = static_cast<int>(scenario_.milestones.size());
  draw_plan_bar_section(layout.bar, scenario_.scene, mirror_, plan_.get(), milestones, state_);
  ImGui::SetNextWindowPos(ImVec2(layout.search.x, layout.search.y));
  ImGui::SetNextWindowSize(ImVec2(layout.search.w, layout.search.h));
  ImGui::Begin("Search", nullptr, kSideWindow);
  draw_controls_section(driver_, mirror_, {milestones, search_elapsed_s_, &goal_stance_}, state_);
  draw_tree_section(scenario_.scene, mirror_, state_);
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(layout.inspector.x, layout.inspector.y));
  ImGui::SetNextWindowSize(ImVec2(layout.inspector.w, layout.inspector.h));
  ImGui::Begin("Inspector", nullptr, kSideWindow);
  if (ImGui::BeginTabBar("inspector tabs")) {
    const auto tab_flags = [&](int tab) {
      return state_.open_tab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
    };
    if (ImGui::BeginTabItem("Inspector", nullptr, tab_flags(0))) {
      draw_node_section(scenario_.scene, mirror_, shown, shown_title(shown),
                        scenario_.solver.tolerance, state_);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Plots", nullptr, tab_flags(1))) {
      draw_plots_section(scenario_.scene, mirror_, plan_.get(), state_);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  state_.open_tab = -1;
  ImGui::End();
}

// Space run / pause; Right step event (while searching) or next plan step; Left previous plan
// step; E step expansion; M next milestone; Home reset view; R run again once the search ended.
// Not while a text field has the keyboard. GLFW's key codes of letters are their ASCII capitals,
// and ImGui 1.86's GLFW backend indexes KeysDown by them.
void PanelApp::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  const auto named = [&](ImGuiKey key) { return pressed(ImGui::GetKeyIndex(key)); };
  const bool live = !mirror_.finished();
  if (live && named(ImGuiKey_Space))
    driver_.mode() == RunMode::Running ? driver_.pause() : driver_.run();
  if (live && named(ImGuiKey_RightArrow)) driver_.step_event();
  if (live && pressed('E')) driver_.step_expansion();
  if (live && pressed('M')) driver_.next_milestone();
  if (named(ImGuiKey_Home)) state_.reset_camera = true;
  if (!live && pressed('R')) state_.rerun = true;
  if (plan_ && (named(ImGuiKey_RightArrow) || named(ImGuiKey_LeftArrow))) {
    const int last = static_cast<int>(plan_->steps.size()) - 1;
    // Between two steps (in a motion), the arrows go to the step before or after.
    const int delta = named(ImGuiKey_RightArrow) ? 1 : state_.step_fraction > 0.0 ? 0 : -1;
    show_plan_step(state_, std::clamp(state_.plan_step + delta, 0, last));
    state_.playing = false;
  }
}

}  // namespace panel_detail

int run_panel(const PanelOptions& options, std::ostream& out, std::ostream& err) {
  Scenario scenario = load_scenario(options.scenario);
  print_computed_collision_matrices(scenario.scene, err);
  print_model_warnings(scenario.scene, err);
  // No guide: computed before the session forks its solver processes (app/pipeline.h).
  if (const std::optional<ComputedGuide> guide = complete_scenario_guide(scenario);
      guide && guide->status != GuideStatus::Computed) {
    err << "stanceplan: no plan: " << guide->message << "\n";
    return kExitFailed;
  }
  std::vector<gui::ScriptAction> script;
  if (!options.script.empty()) script = gui::read_panel_script(options.script);
  std::unique_ptr<panel_detail::PanelApp> app;
  try {
    app = std::make_unique<panel_detail::PanelApp>(scenario, options, std::move(script));
  } catch (const std::runtime_error& e) {  // no display, no GL context
    err << "stanceplan: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  const panel_detail::CloseOnSignal close_on_signal;
  return app->run(out, err);
}

}  // namespace stanceplan::app
