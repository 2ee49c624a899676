#pragma once
// The panel's object (panel_app.h has its entry point): the window, the session, the render
// thread and the panel state, one loop turn at a time. Its parts live in panel_app.cpp (the loop,
// the frame and the view), panel_requests.cpp (what buttons and shortcuts asked for: exports,
// re-run, the end of the search) and panel_scripted.cpp (--script: actions, mouse moves, reports).
// Internal to app/gui.
#include <atomic>
#include <chrono>
#include <deque>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/gui_window.h"
#include "app/gui/orbit_camera.h"
#include "app/gui/panel_app.h"
#include "app/gui/panel_layout.h"
#include "app/gui/panel_state.h"
#include "app/gui/script_runner.h"
#include "app/gui/search_driver.h"
#include "app/gui/session_mirror.h"
#include "app/gui/view_renderer.h"
#include "app/gui/view_texture.h"
#include "app/live/motion_session.h"
#include "app/live/plan_session.h"
#include "planner/io/scenario.h"
#include "planner/plan/plan_timeline.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::app::panel_detail {

using Clock = std::chrono::steady_clock;

// SIGINT / SIGTERM received (0: none): the loop closes the window as if the user had.
extern std::atomic<int> g_close_signal;

class PanelApp {
 public:
  PanelApp(const Scenario& scenario, const PanelOptions& options,
           std::vector<gui::ScriptAction> script);
  // Until the window closes: kExitSuccess, or kExitFailed when a script action failed.
  int run(std::ostream& out, std::ostream& err);

 private:
  // panel_app.cpp
  void pace(double dt_s, std::ostream& out, std::ostream& err);
  bool needs_frame();
  void draw_frame(double dt_s, bool last, std::ostream& out, std::ostream& err);
  void frame(bool last, std::ostream& out, std::ostream& err);
  void draw_windows(long shown, const gui::PanelLayout& layout);
  void handle_shortcuts();
  TimelinePoint timeline_at() const;  // where the timeline is (a step, or a motion sample)
  long shown_event() const;
  std::string shown_title(long shown) const;
  gui::ViewRequest view_request(long shown, const gui::Rect& area) const;
  void update_view(long shown, const gui::Rect& area, bool wait);
  double stop_search();
  // panel_requests.cpp
  void on_search_finished(std::ostream& out, std::ostream& err);
  void sync_motion(std::ostream& out, std::ostream& err);
  void on_motion_finished(const MotionProgress& progress, std::ostream& out, std::ostream& err);
  void carry_out_requests(long shown, const gui::Rect& area);
  void carry_out_exports(long shown, const gui::Rect& area);
  void carry_out_failure_requests();
  void rerun();
  // panel_scripted.cpp
  void advance_script(std::ostream& out, std::ostream& err);
  void carry_out(const gui::ScriptAction& action, std::ostream& out);
  void carry_out_view_action(const gui::ScriptAction& action, std::ostream& out);
  gui::ScriptProgress progress() const;
  std::string status_text() const;
  std::string shown_summary() const;

  const Scenario& scenario_;
  PanelOptions options_;
  // Made first: its solver worker processes fork before the window, GL and the render thread
  // start any thread (solver_pool.h).
  std::unique_ptr<PlanSession> session_;
  gui::GuiWindow window_;
  std::shared_ptr<render::MeshLibrary> meshes_;
  render::RenderStyle style_;
  gui::ViewRenderer view_;
  gui::ViewTexture texture_;
  gui::SearchDriver driver_;
  const Stance goal_stance_;
  gui::SessionMirror mirror_;
  gui::PanelState state_;
  gui::OrbitCamera camera_, framed_;
  std::shared_ptr<const Plan> plan_;  // the plan found, once the search has found it
  // The motion between its steps, computed after the search (--no-motion: never); plan_ is
  // replaced by a copy with the motions computed so far as they arrive.
  std::unique_ptr<MotionSession> motion_;
  int motion_steps_shown_ = 0;  // the motions plan_ holds (steps tried)
  bool motion_handled_ = false;
  int drawn_motion_steps_ = 0;
  Clock::time_point search_start_;
  double search_elapsed_s_ = 0.0;
  bool finish_handled_ = false;
  // What the last frame drawn showed, to draw again only on news (needs_frame).
  long seen_input_ = -1;
  size_t drawn_events_ = 0;
  bool drawn_finished_ = false;
  int settle_frames_ = 0;
  std::string last_view_key_;
  std::uint64_t last_view_id_ = 0;
  std::vector<double> frame_ms_;
  // --script
  std::optional<gui::ScriptRunner> script_;
  std::deque<gui::ScriptedPointer> pointer_moves_;  // one per frame still to draw
  std::string pending_screenshot_;                  // written at the end of the next frame
  bool script_failed_ = false;
};

}  // namespace stanceplan::app::panel_detail
