#include "app/gui/view_renderer.h"

#include <algorithm>
#include <utility>

#include "app/gui/guide_overlay.h"
#include "planner/util/fork_gate.h"

namespace stanceplan::gui {

using Clock = std::chrono::steady_clock;

ViewRenderer::ViewRenderer(const Scene& scene, const render::RenderStyle& style,
                           std::shared_ptr<render::MeshLibrary> meshes)
    : scene_(scene), style_(style), meshes_(std::move(meshes)), thread_([this] { loop(); }) {}

ViewRenderer::~ViewRenderer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::uint64_t ViewRenderer::request(ViewRequest request) {
  std::uint64_t id;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(request);
    id = ++next_id_;
  }
  wake_.notify_all();
  return id;
}

std::optional<ViewFrame> ViewRenderer::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<ViewFrame> frame = std::move(finished_);
  finished_.reset();
  return frame;
}

bool ViewRenderer::has_news() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return finished_.has_value() || !messages_.empty();
}

bool ViewRenderer::wait_for(std::uint64_t id, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  return done_.wait_for(lock, timeout, [&] { return rendered_id_ >= id; });
}

void ViewRenderer::post(Job job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  wake_.notify_all();
}

std::vector<std::string> ViewRenderer::take_messages() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(messages_, {});
}

double ViewRenderer::median_render_ms() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (render_ms_.empty()) return 0.0;
  std::vector<double> sorted = render_ms_;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  return sorted[sorted.size() / 2];
}

int ViewRenderer::frames_rendered() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(render_ms_.size());
}

void ViewRenderer::loop() {
  while (true) {
    std::optional<ViewRequest> request;
    std::optional<Job> job;
    std::uint64_t id = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || pending_ || !jobs_.empty(); });
      if (stop_) break;
      if (!jobs_.empty()) {
        job = std::move(jobs_.front());
        jobs_.pop_front();
      } else {
        request = std::move(pending_);
        pending_.reset();
        id = next_id_;
      }
    }
    const ForkGate::Pass pass;  // the search forks between renders (planner/util/fork_gate.h)
    try {
      if (job) {
        if (!renderer_) renderer_ = std::make_unique<render::Renderer>(64, 64, style_, meshes_);
        const std::string message = (*job)(*renderer_);
        std::lock_guard<std::mutex> lock(mutex_);
        if (!message.empty()) messages_.push_back(message);
      } else {
        render_one(std::move(*request), id);
      }
    } catch (const std::exception& e) {  // no OSMesa context, an unwritable export, ...
      std::lock_guard<std::mutex> lock(mutex_);
      messages_.push_back(std::string("error: ") + e.what());
      if (!job) rendered_id_ = std::max(rendered_id_, id);  // nobody waits for it in vain
      done_.notify_all();
    }
  }
  renderer_.reset();  // the OSMesa context is destroyed on the thread that made it
}

void ViewRenderer::render_one(ViewRequest request, std::uint64_t id) {
  const auto start = Clock::now();
  if (!renderer_ || renderer_->width() != request.width || renderer_->height() != request.height)
    renderer_ = std::make_unique<render::Renderer>(request.width, request.height, style_, meshes_);
  renderer_->set_style(style_);  // a job may have changed it
  ViewFrame frame;
  frame.image =
      request.ghost_q
          ? render_with_ghost(*renderer_, scene_, request.q, request.contacts, request.forces,
                              *request.ghost_q, request.camera, request.caption)
          : renderer_->render(scene_, request.q, request.contacts, request.forces, request.camera,
                              request.caption);
  frame.request = id;
  frame.render_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  for (const std::string& w : renderer_->take_warnings()) {
    std::lock_guard<std::mutex> lock(mutex_);
    messages_.push_back("warning: " + w);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    render_ms_.push_back(frame.render_ms);
    rendered_id_ = std::max(rendered_id_, id);
    finished_ = std::move(frame);
  }
  done_.notify_all();
}

}  // namespace stanceplan::gui
