#pragma once
// Off-screen rendering of a scene at a configuration with its contact information, to an RGBA
// image, through OSMesa (no display, no X server).
//
// Threading: a Renderer owns an OpenGL context, and GL contexts are bound to one thread. Create
// a Renderer on the thread that will render with it, call it from that thread only and destroy
// it there (the app gives live snapshots one dedicated thread). It is not thread-safe; separate
// threads need separate Renderers (they may share one MeshLibrary, which is). Several Renderers
// may live on one thread: each call makes its own context current. For live snapshots,
// RenderStyle::preview() costs about two thirds of the default (figure) style.
//
// Determinism: the same inputs give the same pixels (no time-dependent state, no random numbers).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "planner/plan/plan.h"
#include "planner/scene/scene.h"
#include "render/image/image.h"
#include "render/render_style.h"
#include "render/scene/camera.h"
#include "render/scene/draw_list.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::render {

class Renderer {
 public:
  // Throws std::runtime_error when no OpenGL context can be created. `meshes` may be shared with
  // other renderers (each mesh file is then loaded once); a new library is made when null.
  Renderer(int width, int height, const RenderStyle& style = {},
           std::shared_ptr<MeshLibrary> meshes = nullptr);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders every entity of `scene` at the system configuration q, the contacts (s1 surfaces
  // highlighted, loaded or not), the vertex forces (VertexForce::contact indexes `contacts`),
  // each floating robot's centre of mass and the support polygon; then the caption ('\n'
  // separates lines, the first is bold) and the legend. Returns top-down RGBA rows.
  // Throws std::invalid_argument when q does not fit the scene's system.
  Image render(const Scene& scene, const Eigen::VectorXd& q,
               const std::vector<PlanContact>& contacts, const std::vector<VertexForce>& forces,
               const Camera& camera, const std::string& caption = "");
  // Renders prepared draw items (no caption, no legend): the lower-level entry point.
  Image render(const DrawList& list, const Camera& camera);

  // Draw items of a frame, without GL: what render() draws, and what framing uses.
  DrawList assemble(const Scene& scene, const Eigen::VectorXd& q,
                    const std::vector<PlanContact>& contacts,
                    const std::vector<VertexForce>& forces) const;
  // The camera framing the robots, objects and contact surfaces at q from a named view.
  Camera frame(const Scene& scene, const Eigen::VectorXd& q,
               const std::vector<PlanContact>& contacts, View view) const;

  int width() const;
  int height() const;
  const RenderStyle& style() const;
  void set_style(const RenderStyle& style);
  MeshLibrary& meshes() const;
  // Warnings (missing or unreadable visual meshes, model load warnings) not yet taken.
  std::vector<std::string> take_warnings();
  std::string gl_renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The margins automatic framing leaves for a style: room for the caption at the top and the
// legend at the bottom when they are drawn.
FrameMargins frame_margins(const RenderStyle& style);

}  // namespace stanceplan::render
