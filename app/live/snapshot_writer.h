#pragma once
// Live snapshots of a running search: every event of a PlanSession becomes a PNG in a
// folder, named by event number and kind (event_record.h), plus the index events.jsonl with one
// line per event. Rendering and PNG encoding run on the writer's own thread at the lowest CPU
// priority (thread_priority.h: the renderer's llvmpipe threads inherit it) so that they take the
// cores only when the search does not need them, and at the normal priority again once the search
// ended. The writer never holds the search: when it falls behind, the events wait in the session
// and the backlog is drawn after the search ends.
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "app/live/plan_session.h"

namespace stanceplan::app {

struct SnapshotOptions {
  std::string dir;       // created if missing; stale event_*.png files in it are removed
  bool rejected = true;  // false: rejected candidates are listed without an image
  int width = 960;
  int height = 540;
};

struct SnapshotStats {
  int events = 0;                 // lines of events.jsonl
  int images = 0;                 // PNG files written
  int backlog_at_search_end = 0;  // events without their image when the search finished
  double image_ms_median = 0.0;   // render + PNG encode + write, per image
  double drain_s = 0.0;           // from the end of the search to the last image
};

class SnapshotWriter {
 public:
  // `session` must outlive the writer.
  SnapshotWriter(const PlanSession& session, SnapshotOptions options);
  ~SnapshotWriter();  // stops the thread (events not yet drawn are left out of the index)
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  void start();
  // After the session finished: waits for the backlog, writes the final events.jsonl and returns
  // the figures. Rethrows what stopped the writer's thread (an unwritable folder, no GL context).
  SnapshotStats finish();
  size_t images_written() const { return images_.load(); }

  static constexpr const char* kIndexFile = "events.jsonl";

 private:
  void run();
  void write_all();
  bool next_event(size_t index);  // false once the session finished without that event
  void write_index(const std::string& lines) const;

  const PlanSession& session_;
  SnapshotOptions options_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<size_t> images_{0};
  std::exception_ptr error_;  // set by the thread, read after join
  SnapshotStats stats_;       // written by the thread, read after join
};

}  // namespace stanceplan::app
