#include "render/scene/scene_assembly.h"

#include <stdexcept>
#include <string>

#include "planner/model/kinematics.h"
#include "render/scene/contact_overlays.h"
#include "render/scene/ground.h"

namespace stanceplan::render {
namespace {

Color to_color(const Eigen::Vector4d& rgba) {
  return Color{static_cast<float>(rgba[0]), static_cast<float>(rgba[1]),
               static_cast<float>(rgba[2]), static_cast<float>(rgba[3])};
}

// Returns false (and warns) when the geometry cannot be drawn.
bool add_geometry(const LinkGeometry& geometry, const Eigen::Isometry3d& T_WL,
                  const std::string& where, const RenderStyle& style, MeshLibrary& meshes,
                  DrawItem* item) {
  const Eigen::Isometry3d T_WG = T_WL * geometry.T_LG;
  const Shape& shape = geometry.shape;
  item->color = geometry.has_color ? to_color(geometry.rgba) : style.default_color;
  switch (shape.type) {
    case ShapeType::Box:
      item->mesh = &MeshLibrary::primitive(ShapeType::Box);
      item->T_WM = scaled_transform(T_WG, shape.size);
      return true;
    case ShapeType::Cylinder:
      item->mesh = &MeshLibrary::primitive(ShapeType::Cylinder);
      item->T_WM =
          scaled_transform(T_WG, Eigen::Vector3d(shape.size[0], shape.size[0], shape.size[1]));
      return true;
    case ShapeType::Sphere:
      item->mesh = &MeshLibrary::primitive(ShapeType::Sphere);
      item->T_WM = scaled_transform(T_WG, Eigen::Vector3d::Constant(shape.size[0]));
      return true;
    case ShapeType::Mesh: {
      if (shape.mesh_path.empty()) {
        meshes.warn(where + ": mesh \"" + shape.mesh_uri + "\" was not found (visual skipped)");
        return false;
      }
      const LoadedMesh* loaded = meshes.file(shape.mesh_path, shape.mesh_scale);
      if (loaded == nullptr) return false;
      item->mesh = &loaded->mesh;
      item->T_WM = T_WG.matrix().cast<float>();
      // The file's own materials (DAE, OBJ, ...) win over the URDF's <material>, which colours
      // only files without any (STL), as rviz does: a published model looks as its author drew it.
      item->vertex_colors = loaded->has_material_colors;
      return true;
    }
  }
  return false;
}

}  // namespace

SystemPose::SystemPose(const System& system, const Eigen::VectorXd& q) {
  if (q.size() != system.nq())
    throw std::invalid_argument("configuration has " + std::to_string(q.size()) +
                                " entries, the system needs " + std::to_string(system.nq()));
  data_.reserve(system.num_entities());
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    data_.emplace_back(entity);
    forward_kinematics(entity, q.segment(system.offset(e), entity.nq()), data_.back());
  }
}

void add_entity_geometry(const Scene& scene, const SystemPose& pose, const RenderStyle& style,
                         MeshLibrary& meshes, DrawList& list) {
  for (int e = 0; e < scene.system.num_entities(); ++e) {
    const Entity& entity = scene.system.entity(e);
    const bool environment = entity.kind == EntityKind::Environment;
    list.has_environment |= environment;
    for (const std::string& warning : entity.model->load_warnings) meshes.warn(warning);
    const Model& model = *entity.model;
    for (int l = 0; l < model.num_links(); ++l) {
      const Link& link = model.links[l];
      const auto& geometries = style.collision_geometry ? link.collisions : link.visuals;
      for (const LinkGeometry& geometry : geometries) {
        DrawItem item;
        const std::string where = entity.name + "/" + link.name;
        if (!add_geometry(geometry, pose.T_WL(e, l), where, style, meshes, &item)) continue;
        // A mesh in its own colours is opaque whatever the URDF's alpha says.
        item.layer =
            item.color.a < 0.99f && !item.vertex_colors ? Layer::Translucent : Layer::Solid;
        item.frames_view = !environment;
        item.environment = environment;
        list.items.push_back(item);
      }
    }
  }
}

DrawList assemble_frame(const Scene& scene, const Eigen::VectorXd& q,
                        const std::vector<PlanContact>& contacts,
                        const std::vector<VertexForce>& forces, const RenderStyle& style,
                        MeshLibrary& meshes) {
  const SystemPose pose(scene.system, q);
  DrawList list;
  add_entity_geometry(scene, pose, style, meshes, list);
  list.ground = find_ground(list);
  add_contact_overlays(scene, pose, contacts, forces, style, list);
  return list;
}

}  // namespace stanceplan::render
