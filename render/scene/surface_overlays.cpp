#include "render/scene/surface_overlays.h"

#include <algorithm>
#include <array>

#include "render/scene/mesh_library.h"

namespace stanceplan::render {
namespace {

constexpr double kLift = 0.003;  // patches float this far off their link, along the normal

// Twelve hues far apart, dark enough for white-background labels to stay readable.
constexpr std::array<std::uint32_t, 12> kPalette = {0x1f77b4, 0xd62728, 0x2ca02c, 0x9467bd,
                                                    0xff7f0e, 0x17becf, 0x8c564b, 0xe377c2,
                                                    0x7f7f7f, 0xbcbd22, 0x393b79, 0x637939};

DrawItem patch_item(DrawList& list, MeshData mesh, Color color) {
  DrawItem item;
  item.mesh = list.keep(std::move(mesh));
  item.transient = true;
  item.color = color;
  item.layer = Layer::Decal;
  item.casts_shadow = false;
  item.frames_view = true;
  return item;
}

// One surface: the filled polygon (translucent) and its ring (opaque), lifted along the normal.
// A point surface (a round fingertip): a sphere of its radius (at least 4 mm, to be seen) at its
// centre, seen through the link that holds it, labelled there.
SurfaceLabel add_point(const Surface& surface, const Eigen::Isometry3d& T_WL, const std::string& id,
                       Color color, DrawList& list) {
  const Eigen::Vector3d c_W = T_WL * surface.center_L();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = c_W;
  DrawItem item;
  item.mesh = &MeshLibrary::primitive(ShapeType::Sphere);
  item.T_WM = scaled_transform(T, Eigen::Vector3d::Constant(std::max(surface.radius, 0.004)));
  item.color = color;
  item.casts_shadow = false;
  item.xray = true;  // inside the fingertip it belongs to: drawn faded through it
  item.frames_view = true;
  list.items.push_back(item);
  return {id, c_W, color, true};
}

SurfaceLabel add_surface(const Surface& surface, const Eigen::Isometry3d& T_WL,
                         const std::string& id, Color color, const RenderStyle& style,
                         DrawList& list) {
  if (surface.is_point()) return add_point(surface, T_WL, id, color, list);
  const Eigen::Vector3d n_W = T_WL.linear() * surface.normal_L();
  std::vector<Eigen::Vector3f> vertices;
  for (const Eigen::Vector3d& p_L : surface.vertices_L())
    vertices.push_back((T_WL * p_L + kLift * n_W).cast<float>());
  const Eigen::Vector3f n = n_W.cast<float>();
  Color fill = color;
  fill.a = 0.45f;
  list.items.push_back(patch_item(list, polygon(vertices, n), fill));
  list.items.push_back(patch_item(
      list, polygon_ring(vertices, n, static_cast<float>(0.5 * style.contact_ring_width)), color));
  const Eigen::Vector2d c_S = surface.centroid_S();
  const Eigen::Vector3d p_L = surface.T_LS * Eigen::Vector3d(c_S.x(), c_S.y(), 0.0);
  return {id, T_WL * p_L + kLift * n_W, color};
}

}  // namespace

Color surface_color(int index) {
  return rgb_hex(kPalette[static_cast<size_t>(index) % kPalette.size()]);
}

std::vector<SurfaceLabel> add_surface_overlays(const Scene& scene, const SystemPose& pose,
                                               const RenderStyle& style, DrawList& list) {
  std::vector<SurfaceLabel> labels;
  for (int e = 0; e < scene.surfaces.num_entities(); ++e) {
    const std::vector<Surface>& surfaces = scene.surfaces.of(e);
    for (int i = 0; i < static_cast<int>(surfaces.size()); ++i) {
      const std::string id = scene.surfaces.id(scene.system, SurfaceRef{e, i});
      const Color color = surface_color(static_cast<int>(labels.size()));
      labels.push_back(
          add_surface(surfaces[i], pose.T_WL(e, surfaces[i].link), id, color, style, list));
    }
  }
  return labels;
}

bool project_to_pixel(const Camera& camera, int width, int height, const Eigen::Vector3d& p_W,
                      Eigen::Vector2d& pixel) {
  const double aspect = static_cast<double>(width) / height;
  const Eigen::Vector4d clip =
      camera.projection_matrix(aspect, 0.01, 100.0) * camera.view_matrix() * p_W.homogeneous();
  if (clip.w() <= 0.0) return false;
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  pixel = Eigen::Vector2d(0.5 * (ndc.x() + 1.0) * width, 0.5 * (1.0 - ndc.y()) * height);
  return true;
}

}  // namespace stanceplan::render
