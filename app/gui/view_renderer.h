#pragma once
// The 3-D view's pictures, made by render::Renderer (OSMesa) on a thread of its own: the same
// renderer and look as the PNGs, and the window's thread never waits for a frame.
//
// Why a thread (docs/DEPENDENCIES.md section 5): an OSMesa context and the window's GLX context
// made current in turn on one thread need each released before the other is bound, and that works
// only because both are Mesa. GL contexts are per thread, so with OSMesa current on this thread and
// the window's context current on the panel's thread neither is ever switched; the panel uploads
// the finished RGBA image into a texture of its own context. Rendering (30-70 ms at 1280x720 on
// llvmpipe) also stays off the panel's frame time.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "planner/scene/scene.h"
#include "render/renderer.h"

namespace stanceplan::gui {

struct ViewRequest {
  Eigen::VectorXd q;
  std::vector<PlanContact> contacts;
  std::vector<VertexForce> forces;
  render::Camera camera;
  std::string caption;
  // The configuration of the milestone aimed at, drawn as a translucent ghost (guide_overlay.h).
  std::optional<Eigen::VectorXd> ghost_q;
  int width = 0;
  int height = 0;
};

struct ViewFrame {
  render::Image image;
  std::uint64_t request = 0;  // the number request() returned
  double render_ms = 0.0;
};

class ViewRenderer {
 public:
  // Starts the render thread; the Renderer (and its OSMesa context) is made on it. `scene` must
  // outlive this object.
  ViewRenderer(const Scene& scene, const render::RenderStyle& style,
               std::shared_ptr<render::MeshLibrary> meshes);
  ~ViewRenderer();  // finishes the frame or job in progress, then joins
  ViewRenderer(const ViewRenderer&) = delete;
  ViewRenderer& operator=(const ViewRenderer&) = delete;

  // Replaces any request not yet started (only the newest view matters); returns its number.
  std::uint64_t request(ViewRequest request);
  // The newest finished frame not yet taken.
  std::optional<ViewFrame> take();
  // Whether take() has a frame or take_messages() a message.
  bool has_news() const;
  // Blocks until the request numbered `id` (or a newer one) is rendered, or the timeout.
  bool wait_for(std::uint64_t id, std::chrono::milliseconds timeout);

  // A job run on the render thread before the next frame (exports). Its returned message, and
  // renderer failures, come back through take_messages().
  using Job = std::function<std::string(render::Renderer& renderer)>;
  void post(Job job);
  std::vector<std::string> take_messages();

  // Median render time of the frames so far (ms), and how many.
  double median_render_ms() const;
  int frames_rendered() const;

 private:
  void loop();
  void render_one(ViewRequest request, std::uint64_t id);

  const Scene& scene_;
  render::RenderStyle style_;
  std::shared_ptr<render::MeshLibrary> meshes_;
  std::unique_ptr<render::Renderer> renderer_;  // only touched on the render thread

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  bool stop_ = false;
  std::optional<ViewRequest> pending_;
  std::uint64_t next_id_ = 0;
  std::uint64_t rendered_id_ = 0;
  std::optional<ViewFrame> finished_;
  std::deque<Job> jobs_;
  std::vector<std::string> messages_;
  std::vector<double> render_ms_;
  std::thread thread_;
};

}  // namespace stanceplan::gui
