#pragma once
// Turns a Scene at a configuration into draw items: forward kinematics of every entity, then each
// link's URDF visual (or collision) geometry placed in the world with its colour.
#include <Eigen/Core>
#include <vector>

#include "planner/model/model_data.h"
#include "planner/plan/plan.h"
#include "planner/scene/scene.h"
#include "render/render_style.h"
#include "render/scene/draw_list.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::render {

// Forward kinematics of every entity of a system at q (the full system configuration).
class SystemPose {
 public:
  // Throws std::invalid_argument when q does not have system.nq() entries.
  SystemPose(const System& system, const Eigen::VectorXd& q);

  const ModelData& data(int entity) const { return data_[entity]; }
  const Eigen::Isometry3d& T_WL(int entity, int link) const { return data_[entity].T_WL[link]; }

 private:
  std::vector<ModelData> data_;
};

// Adds the geometry of every entity. A mesh that cannot be loaded is skipped and recorded as a
// warning in `meshes` (once per file), as are the models' own load warnings (unresolved visuals).
void add_entity_geometry(const Scene& scene, const SystemPose& pose, const RenderStyle& style,
                         MeshLibrary& meshes, DrawList& list);

// Everything a frame draws (geometry, its ground (ground.h) and contact overlays, see
// contact_overlays.h), without GL.
DrawList assemble_frame(const Scene& scene, const Eigen::VectorXd& q,
                        const std::vector<PlanContact>& contacts,
                        const std::vector<VertexForce>& forces, const RenderStyle& style,
                        MeshLibrary& meshes);

}  // namespace stanceplan::render
