#include "app/live/snapshot_writer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <future>
#include <regex>
#include <stdexcept>

#include "app/live/event_record.h"
#include "app/live/thread_priority.h"
#include "planner/util/atomic_file.h"
#include "render/image/png_io.h"
#include "render/renderer.h"

namespace stanceplan::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kPoll{100};
constexpr double kIndexPeriodS = 1.0;   // events.jsonl is rewritten at most this often while live
constexpr double kFramePadding = 0.15;  // m around the guide path: candidates stray from it

// What a snapshot draws: the configuration, the contacts touched there and the forces.
struct Pose {
  Eigen::VectorXd q;
  std::vector<PlanContact> contacts;
  std::vector<VertexForce> forces;
};

void remove_stale_snapshots(const std::filesystem::path& dir) {
  static const std::regex kName(R"(event_\d{5}_[a-z_]+\.png)");
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kName))
      std::filesystem::remove(entry.path());
}

// One framing for every snapshot of the search, so that they line up: the scene at the initial
// configuration and at every milestone of the guide path, plus a margin.
render::Camera snapshot_camera(render::Renderer& renderer, const Scenario& scenario) {
  Eigen::AlignedBox3d box =
      renderer.assemble(scenario.scene, scenario.initial_configuration, {}, {}).bounds();
  for (const Eigen::VectorXd& q : scenario.milestones)
    box.extend(renderer.assemble(scenario.scene, q, {}, {}).bounds());
  if (box.isEmpty())
    box = renderer.assemble(scenario.scene, scenario.initial_configuration, {}, {}).bounds(true);
  box.min().array() -= kFramePadding;
  box.max().array() += kFramePadding;
  const double aspect = double(renderer.width()) / renderer.height();
  return render::frame_box(box, render::View::ThreeQuarter, aspect,
                           render::frame_margins(renderer.style()));
}

std::vector<PlanContact> stance_contacts(const Stance& stance, bool loaded) {
  std::vector<PlanContact> out;
  for (const Contact& c : stance.contacts()) out.push_back({c, loaded});
  return out;
}

// Candidates and expansions carry their pose. Milestones and the found plan carry q only (their
// contacts are the stance's). A failure carries none: the closest node, from the result.
Pose event_pose(const SearchEvent& e, const PlanSession& session) {
  const Scenario& scenario = session.scenario();
  const long nq = scenario.initial_configuration.size();
  if (e.q.size() == nq) {
    if (!e.contacts.empty() || e.kind == SearchEventKind::Candidate ||
        e.kind == SearchEventKind::Expansion)
      return {e.q, e.contacts, e.forces};
    return {e.q, stance_contacts(e.stance, true), {}};  // a node's stance: all loaded
  }
  if (e.kind == SearchEventKind::Failure && e.node >= 0) {
    while (!session.wait_until_finished(kPoll)) {
    }
    const std::optional<SearchResult> result = session.result();
    if (result && e.node < int(result->tree.size())) {
      const PlanStep& step = result->tree[e.node].step;
      return {step.q, step.contacts, step.forces};
    }
  }
  return {scenario.initial_configuration, stance_contacts(e.stance, false), {}};
}

bool wants_image(const SearchEvent& e, const SnapshotOptions& options) {
  return options.rejected || e.kind != SearchEventKind::Candidate || e.accepted;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

SnapshotWriter::SnapshotWriter(const PlanSession& session, SnapshotOptions options)
    : session_(session), options_(std::move(options)) {
  try {
    std::filesystem::create_directories(options_.dir);
    remove_stale_snapshots(options_.dir);
  } catch (const std::filesystem::filesystem_error& e) {
    throw std::runtime_error(options_.dir + ": cannot prepare the snapshot folder (" +
                             e.code().message() + ")");
  }
}

SnapshotWriter::~SnapshotWriter() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void SnapshotWriter::start() {
  // Returns once the thread runs: its start (the C++ runtime's and a sanitizer's allocations) is
  // over before the caller lets the search fork its workers (plan_command.cpp, fork_gate.h).
  std::promise<void> running;
  std::future<void> started = running.get_future();
  thread_ = std::thread([this, &running] {
    running.set_value();
    run();
  });
  started.wait();
}

SnapshotStats SnapshotWriter::finish() {
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
  return stats_;
}

void SnapshotWriter::run() {
  try {
    write_all();
  } catch (...) {
    error_ = std::current_exception();
  }
}

bool SnapshotWriter::next_event(size_t index) {
  while (!session_.wait_for_event(index, kPoll)) {
    if (stop_) return false;
    if (session_.finished() && session_.event_count() <= index) return false;
  }
  return !stop_;
}

void SnapshotWriter::write_index(const std::string& lines) const {
  write_file_atomically((std::filesystem::path(options_.dir) / kIndexFile).string(), lines);
}

void SnapshotWriter::write_all() {
  // The GL context (and llvmpipe's threads) are made once the first event exists: the search
  // forks its solver processes before its first event, and forks should copy as few threads as
  // possible.
  BackgroundPriority priority;  // before the renderer, whose threads inherit it
  if (!next_event(0)) return write_index("");
  const Scenario& scenario = session_.scenario();
  render::Renderer renderer(options_.width, options_.height, render::RenderStyle::preview());
  const render::Camera camera = snapshot_camera(renderer, scenario);
  const int milestones = static_cast<int>(scenario.milestones.size());
  std::string lines;
  std::vector<double> image_ms;
  auto last_index = Clock::now();
  std::optional<Clock::time_point> search_end;
  for (size_t i = 0; next_event(i); ++i) {
    if (!search_end && session_.finished()) {
      search_end = Clock::now();
      stats_.backlog_at_search_end = static_cast<int>(session_.event_count() - i);
      priority.restore();  // the cores are free now: draw the backlog at the normal priority
    }
    const SearchEvent e = session_.event(i);
    std::string image;
    if (wants_image(e, options_)) {
      const auto t0 = Clock::now();
      const Pose pose = event_pose(e, session_);
      image = snapshot_file_name(e);
      render::write_png((std::filesystem::path(options_.dir) / image).string(),
                        renderer.render(scenario.scene, pose.q, pose.contacts, pose.forces, camera,
                                        event_caption(scenario.scene, e, milestones)));
      image_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
      ++images_;
    }
    lines += event_json_line(scenario.scene, e, session_.event_time_s(i), image) + "\n";
    ++stats_.events;
    if (std::chrono::duration<double>(Clock::now() - last_index).count() > kIndexPeriodS) {
      write_index(lines);
      last_index = Clock::now();
    }
  }
  write_index(lines);
  stats_.images = static_cast<int>(images_.load());
  stats_.image_ms_median = median(image_ms);
  if (search_end)
    stats_.drain_s = std::chrono::duration<double>(Clock::now() - *search_end).count();
}

}  // namespace stanceplan::app
