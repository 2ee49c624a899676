#pragma once
// What one frame draws, independent of GL: a list of meshes with their world transforms, colours
// and the pass each belongs to. Built by scene_assembly / contact_overlays, consumed by Renderer.
#include <Eigen/Geometry>
#include <deque>
#include <vector>

#include "render/image/color.h"
#include "render/scene/mesh_data.h"

namespace stanceplan::render {

enum class Layer {
  Solid,        // opaque geometry: links, environment, opaque overlays
  Decal,        // flat overlays lying on a surface (contact patches): pulled towards the camera
  Translucent,  // blended, drawn after the solids without writing depth
};

struct DrawItem {
  const MeshData* mesh = nullptr;
  Eigen::Matrix4f T_WM = Eigen::Matrix4f::Identity();  // mesh frame -> world, scale included
  Color color;
  bool vertex_colors = false;  // use the mesh's per-vertex colours instead of `color`
  Layer layer = Layer::Solid;
  bool casts_shadow = true;
  bool xray = false;           // also drawn faded where hidden (forces, centre of mass)
  float xray_opacity = -1.0f;  // < 0: the style's xray_opacity
  bool frames_view = false;    // counts for automatic framing (robots, objects, contact patches)
  bool environment = false;    // environment geometry: ghosted when it hides the subject
  bool transient = false;      // mesh owned by this frame's DrawList, not by a MeshLibrary
  bool lit = true;             // false: flat colour

  Eigen::AlignedBox3d world_bounds() const;  // the mesh's bounds, transformed
};

// Where the frame's ground is (ground.h decides it from the geometry).
struct Ground {
  double z = 0.0;
  // An environment's floor is the ground: no ground plane is drawn, the grid lies on that floor.
  bool environment_floor = false;
};

struct DrawList {
  std::vector<DrawItem> items;
  std::deque<MeshData> transient_meshes;  // a deque keeps addresses stable while growing
  bool has_environment = false;
  Ground ground;

  // Stores a mesh made for this frame and returns its stable address.
  const MeshData* keep(MeshData mesh) {
    transient_meshes.push_back(std::move(mesh));
    return &transient_meshes.back();
  }
  // World bounds of the items that frame the view; of every item when all_items is true.
  Eigen::AlignedBox3d bounds(bool all_items = false) const;
};

// For each item: true when it is environment geometry standing between the eye and the subject
// (`focus`, sampled at its centre and eight inner points; at least a third of these sight lines
// blocked), so that drawing it opaque would hide the robot, e.g. a wall between the camera and a
// robot touching it.
std::vector<bool> occluding_environment(const DrawList& list, const Eigen::Vector3d& eye,
                                        const Eigen::AlignedBox3d& focus);

// A rigid transform and a per-axis scale as one matrix (T * diag(scale)).
Eigen::Matrix4f scaled_transform(const Eigen::Isometry3d& T, const Eigen::Vector3d& scale);
// The rotation taking +z onto `direction` (any unit vector; stable at +-z).
Eigen::Matrix3d rotation_z_to(const Eigen::Vector3d& direction);

}  // namespace stanceplan::render
