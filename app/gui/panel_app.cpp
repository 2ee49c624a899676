#include "app/gui/panel_app.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

#include "app/exit_codes.h"
#include "app/gui/controls_section.h"
#include "app/gui/gui_window.h"
#include "app/gui/node_section.h"
#include "app/gui/orbit_camera.h"
#include "app/gui/panel_exports.h"
#include "app/gui/panel_layout.h"
#include "app/gui/plan_bar_section.h"
#include "app/gui/search_driver.h"
#include "app/gui/session_mirror.h"
#include "app/gui/tree_section.h"
#include "app/gui/ui_style.h"
#include "app/gui/view_renderer.h"
#include "app/gui/view_section.h"
#include "app/gui/view_texture.h"
#include "app/live/event_record.h"
#include "app/live/plan_session.h"
#include "app/pipeline.h"
#include "app/plan_output.h"
#include "planner/util/fork_gate.h"
#include "render/figures/step_caption.h"
#include "render/image/png_io.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::app {
namespace {

using Clock = std::chrono::steady_clock;
using namespace gui;

constexpr double kFramePeriod = 1.0 / 30.0;  // the panel redraws at most 30 times a second
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

SearchOptions search_options(const Scenario& scenario, const PanelOptions& options) {
  SearchOptions search = scenario.search;
  if (options.threads) search.threads = *options.threads;
  if (options.time_limit) search.time_limit_s = *options.time_limit;
  if (options.max_nodes) search.max_nodes = *options.max_nodes;
  return search;
}

// The live view's look: the cheaper preview style (render_style.h), same colours as the PNGs.
render::RenderStyle live_style(const Scenario& scenario) {
  render::RenderStyle style = render::RenderStyle::preview();
  style.friction = scenario.solver.friction;
  return style;
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

// The panel: owns the window, the session, the render thread and the panel state; one frame()
// per loop turn.
class PanelApp {
 public:
  PanelApp(const Scenario& scenario, const PanelOptions& options)
      : scenario_(scenario),
        options_(options),
        session_(std::make_unique<PlanSession>(scenario, search_options(scenario, options))),
        window_(options.width, options.height, "stanceplan \u2014 " + scenario.name),
        meshes_(std::make_shared<render::MeshLibrary>()),
        style_(live_style(scenario)),
        view_(scenario.scene, style_, meshes_),
        texture_(window_.gl()),
        driver_(session_->gate(), options.start_paused) {
    driver_.set_speed_limit(options.speed_limit);
    state_.speed_limit = static_cast<float>(options.speed_limit);
    state_.export_folder = options.out_dir;
    const PanelLayout layout =
        panel_layout(float(window_.framebuffer_width()), float(window_.framebuffer_height()));
    camera_ = OrbitCamera(
        initial_camera(scenario, style_, *meshes_, layout.view.w / std::max(layout.view.h, 1.0f)));
    framed_ = camera_;
    session_->start();
    search_start_ = Clock::now();
  }

  int run(std::ostream& out, std::ostream& err);

 private:
  void frame(bool last, std::ostream& out, std::ostream& err);
  void sync(double dt_s);
  void on_search_finished(std::ostream& out, std::ostream& err);
  long shown_event() const;
  std::string shown_title(long shown) const;
  ViewRequest view_request(long shown, const Rect& area) const;
  void update_view(long shown, const Rect& area, bool wait);
  void carry_out_requests(long shown, const Rect& area);
  double stop_search();
  bool needs_frame();

  const Scenario& scenario_;
  PanelOptions options_;
  // Made first: its solver worker processes fork before the window, GL and the render thread
  // start any thread (solver_pool.h).
  std::unique_ptr<PlanSession> session_;
  GuiWindow window_;
  std::shared_ptr<render::MeshLibrary> meshes_;
  render::RenderStyle style_;
  ViewRenderer view_;
  ViewTexture texture_;
  SearchDriver driver_;
  SessionMirror mirror_;
  PanelState state_;
  OrbitCamera camera_, framed_;
  std::shared_ptr<const Plan> plan_;  // the plan found, once the search has found it
  Clock::time_point search_start_;
  double search_elapsed_s_ = 0.0;
  bool finish_handled_ = false;
  long seen_input_ = -1;
  int settle_frames_ = 0;
  std::string last_view_key_;
  std::uint64_t last_view_id_ = 0;
  std::vector<double> frame_ms_;
};

int PanelApp::run(std::ostream& out, std::ostream& err) {
  int frames = 0;                         // counted (see frames_after_search)
  Clock::time_point last = Clock::now();  // the last frame drawn
  Clock::time_point turn = last;          // the last loop turn
  while (!window_.should_close()) {
    // At most kFramePeriod between loop turns; input wakes the loop at once.
    window_.wait_events(std::max(kFramePeriod - ms_since(turn) / 1000.0, 0.0));
    turn = Clock::now();
    if (!needs_frame()) continue;  // idle: nothing to redraw, no CPU taken from the search
    const Clock::time_point start = Clock::now();
    const double dt = std::chrono::duration<double>(start - last).count();
    last = start;
    // Scripted runs count their frames from the start, or from the end of the search.
    if (!options_.frames_after_search || mirror_.finished()) ++frames;
    const bool final_frame = options_.exit_after_frames > 0 && frames >= options_.exit_after_frames;
    {
      const ForkGate::Pass pass;  // the search forks between frames (planner/util/fork_gate.h)
      window_.begin_frame();
      sync(dt);
      frame(final_frame, out, err);
    }
    frame_ms_.push_back(ms_since(start));  // the panel's own work: events, drawing, upload
    if (final_frame) window_.request_close();
  }
  const double stop_ms = stop_search();
  out << "panel: " << frame_ms_.size() << " frames, median frame " << std::fixed
      << std::setprecision(1) << median(frame_ms_) << " ms; 3-D view: " << view_.frames_rendered()
      << " images, median render " << view_.median_render_ms() << " ms; search stopped " << stop_ms
      << " ms after the window closed\n";
  return kExitSuccess;
}

// A frame is drawn when something changed: input, a search event, the end of the search, a new
// picture or message from the render thread, playback; and a few more after that, for ImGui's
// hover and active states to settle. Scripted runs draw every frame (they count them).
bool PanelApp::needs_frame() {
  bool changed = options_.exit_after_frames > 0 || state_.playing ||
                 window_.input_events() != seen_input_ || view_.has_news() ||
                 session_->event_count() != mirror_.events().size() ||
                 session_->finished() != mirror_.finished();
  seen_input_ = window_.input_events();
  if (changed) settle_frames_ = 3;
  if (settle_frames_ == 0) return false;
  --settle_frames_;
  return true;
}

// The window closed: cancel the search (it stops between solver iterations) and join its thread.
double PanelApp::stop_search() {
  const Clock::time_point start = Clock::now();
  session_.reset();
  return ms_since(start);
}

void PanelApp::sync(double dt_s) {
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
  if (!plan_) return;
  advance_timeline(state_, static_cast<int>(plan_->steps.size()), dt_s);
  // A node selected on the plan moves the timeline to its step.
  if (state_.source == ViewSource::Node) {
    const std::vector<int> path = mirror_.tree().plan_path();
    const auto on_plan = std::find(path.begin(), path.end(), state_.selected_node);
    if (on_plan != path.end()) state_.plan_step = static_cast<int>(on_plan - path.begin());
  }
}

void PanelApp::on_search_finished(std::ostream& out, std::ostream& err) {
  const SearchResult& result = *mirror_.result();
  search_elapsed_s_ = result.wall_time_s;
  if (result.status != PlanStatus::Found || result.plan.steps.empty()) return;
  plan_ = std::make_shared<const Plan>(result.plan);
  state_.plan_step = static_cast<int>(result.plan.steps.size()) - 1;
  if (state_.source == ViewSource::Latest) state_.source = ViewSource::PlanStep;
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
  } catch (const std::exception& e) {
    state_.messages.push_back(std::string("error: ") + e.what());
    err << "stanceplan: error: " << e.what() << "\n";
  }
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
    case ViewSource::PlanStep: {
      const std::vector<int> path = tree.plan_path();
      if (state_.plan_step < 0 || state_.plan_step >= static_cast<int>(path.size())) return -1;
      return static_cast<long>(tree.node(path[state_.plan_step])->event);
    }
  }
  return -1;
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
    case ViewSource::PlanStep:
      return "Plan step " + std::to_string(state_.plan_step) + " (node " + std::to_string(e.node) +
             ")";
  }
  return "";
}

ViewRequest PanelApp::view_request(long shown, const Rect& area) const {
  ViewRequest r;
  const SearchEvent& e = mirror_.events()[shown];
  r.q = e.q;
  r.contacts = e.contacts;
  r.forces = e.forces;
  r.camera = camera_.camera();
  // The picture has the view's size in framebuffer pixels (larger than window units on HiDPI).
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  r.width = std::max(16, static_cast<int>(area.w * scale.x));
  r.height = std::max(16, static_cast<int>(area.h * scale.y));
  const int milestones = static_cast<int>(scenario_.milestones.size());
  r.caption = state_.source == ViewSource::PlanStep && plan_
                  ? render::step_caption(app::plan_view(scenario_, *plan_), state_.plan_step)
                  : event_caption(scenario_.scene, e, milestones);
  return r;
}

// Asks the render thread for a new picture when what is shown, the camera or the size changed;
// uploads the newest finished one. `wait`: block until the picture asked for is there.
void PanelApp::update_view(long shown, const Rect& area, bool wait) {
  if (shown >= 0) {
    ViewRequest request = view_request(shown, area);
    const render::Camera& c = request.camera;
    std::ostringstream key;
    key << shown << ' ' << int(state_.source) << ' ' << state_.plan_step << ' ' << request.width
        << 'x' << request.height << ' ' << c.eye.transpose() << ' ' << c.target.transpose();
    if (key.str() != last_view_key_) {
      last_view_key_ = key.str();
      last_view_id_ = view_.request(std::move(request));
    }
  }
  if (wait && last_view_id_ > 0) view_.wait_for(last_view_id_, std::chrono::seconds(30));
  if (std::optional<ViewFrame> frame = view_.take()) texture_.upload(frame->image);
}

void PanelApp::carry_out_requests(long shown, const Rect& area) {
  if (state_.reset_camera) camera_ = framed_;
  state_.reset_camera = false;
  if (state_.cancel_search) session_->cancel();
  state_.cancel_search = false;
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

void PanelApp::frame(bool last, std::ostream& out, std::ostream& err) {
  if (mirror_.finished() && !finish_handled_) {
    on_search_finished(out, err);
    finish_handled_ = true;
  }
  const ImVec2 window = ImGui::GetIO().DisplaySize;  // ImGui's units: window coordinates
  const PanelLayout layout = panel_layout(window.x, window.y);
  long shown = shown_event();
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
  update_view(shown, layout.view, last && !options_.screenshot.empty());
  draw_view_section(layout.view, texture_, camera_, state_);
  const int milestones = static_cast<int>(scenario_.milestones.size());
  draw_plan_bar_section(layout.bar, scenario_.scene, mirror_, milestones, state_);
  ImGui::SetNextWindowPos(ImVec2(layout.search.x, layout.search.y));
  ImGui::SetNextWindowSize(ImVec2(layout.search.w, layout.search.h));
  ImGui::Begin("Search", nullptr, kSideWindow);
  draw_controls_section(driver_, mirror_, {milestones, search_elapsed_s_}, state_);
  draw_tree_section(scenario_.scene, mirror_, state_);
  ImGui::End();
  ImGui::SetNextWindowPos(ImVec2(layout.inspector.x, layout.inspector.y));
  ImGui::SetNextWindowSize(ImVec2(layout.inspector.w, layout.inspector.h));
  ImGui::Begin("Inspector", nullptr, kSideWindow);
  draw_node_section(scenario_.scene, mirror_, shown, shown_title(shown), state_);
  ImGui::End();
  carry_out_requests(shown, layout.view);
  for (std::string& m : view_.take_messages()) {
    if (m.rfind("error", 0) == 0) err << "stanceplan: " << m << "\n";
    state_.messages.push_back(std::move(m));
  }
  window_.end_frame(kWindowClear);
  if (last && !options_.screenshot.empty()) {
    render::write_png(options_.screenshot, window_.read_back_buffer());
    out << "panel: window saved to " << options_.screenshot << "\n";
  }
  window_.present();
}

}  // namespace

int run_panel(const PanelOptions& options, std::ostream& out, std::ostream& err) {
  const Scenario scenario = load_scenario(options.scenario);
  std::unique_ptr<PanelApp> app;
  try {
    app = std::make_unique<PanelApp>(scenario, options);
  } catch (const std::runtime_error& e) {  // no display, no GL context
    err << "stanceplan: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  return app->run(out, err);
}

}  // namespace stanceplan::app
