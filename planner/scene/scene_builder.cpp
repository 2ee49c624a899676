#include "planner/scene/scene_builder.h"

#include <memory>

#include "planner/contact/affordances.h"
#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"

namespace stanceplan {

Scene build_scene(const SceneSpec& spec, HullCache* cache) {
  Scene scene;
  scene.gravity = spec.gravity;
  std::vector<std::vector<Surface>> surfaces;
  CollisionOptions collision_options;
  for (const EntitySpec& e : spec.entities) {
    UrdfOptions options;
    options.packages.directories = e.package_paths;
    auto model = std::make_shared<Model>(load_urdf(e.urdf, options));
    if (e.auto_surfaces)
      surfaces.push_back(extract_surfaces(*model, e.T_WB, *e.auto_surfaces));
    else
      surfaces.push_back(e.surfaces.empty() ? std::vector<Surface>{}
                                            : load_surface_file(e.surfaces, *model));
    Entity entity;
    entity.name = e.name;
    entity.kind = e.kind;
    entity.model = model;
    entity.T_WB = e.T_WB;
    scene.system.add(std::move(entity));
    if (!e.srdf.empty()) collision_options.srdf_files.emplace_back(e.name, e.srdf);
  }
  scene.surfaces = SurfaceSet(scene.system.num_entities());
  for (int i = 0; i < scene.system.num_entities(); ++i)
    scene.surfaces.set(i, std::move(surfaces[i]));
  collision_options.disabled_pairs = spec.ignored_pairs;
  collision_options.computed_matrix = spec.collision_matrix;
  if (spec.collision)
    scene.collision = std::make_shared<CollisionModel>(scene.system, collision_options, cache);
  return scene;
}

}  // namespace stanceplan
