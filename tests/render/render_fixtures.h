#pragma once
// Scenes and plans for the renderer's tests: boxes built in code (exact pixel facts), the project's
// humanoid as a multi-step plan file, and TALOS from ../shared/robots.
#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/io/plan_writer.h"
#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/model/urdf_loader.h"
#include "render/render_style.h"
#include "render/scene/camera.h"
#include "tests/support/paths.h"

namespace stanceplan::test {

// Looking along -x at the origin from 5 m, z up, 30 degrees of view: world y runs rightwards in the
// image.
inline render::Camera camera_on_x_axis() {
  render::Camera camera;
  camera.eye = Eigen::Vector3d(5.0, 0.0, 0.0);
  camera.target = Eigen::Vector3d::Zero();
  camera.up = Eigen::Vector3d::UnitZ();
  camera.fov_y_deg = 30.0;
  return camera;
}

struct TestBox {
  Eigen::Vector3d centre;
  Eigen::Vector3d size;
  Eigen::Vector4d rgba;
};

// One fixed, joint-less entity whose only link carries the boxes (so no configuration is needed).
inline Scene boxes_scene(const std::vector<TestBox>& boxes) {
  Model model;
  model.name = "boxes";
  Link link;
  link.name = "base";
  for (const TestBox& b : boxes) {
    LinkGeometry g;
    g.shape.type = ShapeType::Box;
    g.shape.size = b.size;
    g.T_LG.translation() = b.centre;
    g.has_color = true;
    g.rgba = b.rgba;
    link.visuals.push_back(g);
  }
  model.links.push_back(link);
  model.finalize();
  Entity entity;
  entity.name = "boxes";
  entity.kind = EntityKind::FixedRobot;
  entity.model = std::make_shared<const Model>(std::move(model));
  Scene scene;
  scene.system.add(entity);
  scene.surfaces = SurfaceSet(1);
  return scene;
}

inline LinkGeometry box_geometry(const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                                 const Eigen::Vector4d& rgba) {
  LinkGeometry g;
  g.shape.type = ShapeType::Box;
  g.shape.size = size;
  g.T_LG.translation() = centre;
  g.has_color = true;
  g.rgba = rgba;
  return g;
}

// A mesh file's visual; `rgba` is the URDF's <material> colour when given.
inline LinkGeometry mesh_geometry(const std::string& path,
                                  const std::optional<Eigen::Vector4d>& rgba = std::nullopt) {
  LinkGeometry g;
  g.shape.type = ShapeType::Mesh;
  g.shape.mesh_uri = path;
  g.shape.mesh_path = path;
  g.has_color = rgba.has_value();
  if (rgba) g.rgba = *rgba;
  return g;
}

// Adds a joint-less entity of `kind` whose only link carries the geometries (no configuration);
// call finish_scene() once every entity is in.
inline void add_fixed_entity(Scene& scene, const std::string& name, EntityKind kind,
                             const std::vector<LinkGeometry>& geometries) {
  Model model;
  model.name = name;
  Link link;
  link.name = "base";
  link.visuals = geometries;
  model.links.push_back(link);
  model.finalize();
  Entity entity;
  entity.name = name;
  entity.kind = kind;
  entity.model = std::make_shared<const Model>(std::move(model));
  scene.system.add(entity);
}
inline void finish_scene(Scene& scene) {
  scene.surfaces = SurfaceSet(scene.system.num_entities());
}

// An environment whose only geometry is a horizontal slab `size` wide (x, y), 0.1 m thick, its
// top at `top_z`, in `rgba`; and a subject (a fixed robot): a box 0.3 x 0.3 x 0.6 m standing on
// the slab at the origin, in `subject_rgba`.
inline Scene slab_scene(const Eigen::Vector2d& size, double top_z, const Eigen::Vector4d& rgba,
                        const Eigen::Vector4d& subject_rgba) {
  Scene scene;
  add_fixed_entity(scene, "env", EntityKind::Environment,
                   {box_geometry(Eigen::Vector3d(0, 0, top_z - 0.05),
                                 Eigen::Vector3d(size.x(), size.y(), 0.1), rgba)});
  add_fixed_entity(scene, "robot", EntityKind::FixedRobot,
                   {box_geometry(Eigen::Vector3d(0, 0, top_z + 0.3), Eigen::Vector3d(0.3, 0.3, 0.6),
                                 subject_rgba)});
  finish_scene(scene);
  return scene;
}

// Flat colours on a flat background, nothing else: every pixel is either a box colour or the
// background, exactly.
inline render::RenderStyle plain_style() {
  render::RenderStyle style;
  style.lighting = false;
  style.shadows = false;
  style.background_gradient = false;
  style.background_bottom = render::Color{1.0f, 1.0f, 1.0f, 1.0f};
  style.grid = false;
  style.floor = false;
  style.caption = false;
  style.legend = false;
  return style;
}

// A fresh, empty folder of this test process's own (test::temp_dir).
inline std::string fresh_dir(const std::string& name) {
  const std::filesystem::path dir = test::temp_dir("render_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

// The humanoid of scenarios/humanoid_stand.yaml in `num_steps` postures (arms moving), both soles
// on the floor and loaded, each sole vertex carrying an eighth of the weight. Not a solved plan:
// a picture fixture written through the plan writer, read back by the plan reader.
inline std::string write_humanoid_plan(const std::string& dir, int num_steps) {
  const Scenario scenario = load_scenario(source_path("scenarios/humanoid_stand.yaml"));
  const Scene& scene = scenario.scene;
  const int robot = scene.system.find_entity("robot");
  const Entity& entity = scene.system.entity(robot);
  Plan plan;
  for (int i = 0; i < num_steps; ++i) {
    PlanStep step;
    step.action = i == 0 ? "initial" : "add";
    step.q = scenario.initial_configuration;
    const int offset = scene.system.offset(robot) + entity.first_dof();
    for (const char* joint : {"l_shoulder_p", "r_shoulder_p"}) {
      const int dof = entity.model->find_dof(joint);
      if (dof >= 0) step.q[offset + dof] = -0.5 * i;
    }
    for (const StanceContact& c : scenario.initial_stance)
      step.contacts.push_back({c.contact, true});
    if (i > 0) step.changed = step.contacts.back().contact;
    step.stance = scenario.stance(scenario.initial_stance);
    ModelData data(entity);
    forward_kinematics(entity, step.q.segment(scene.system.offset(robot), entity.nq()), data);
    const double weight = entity.model->total_mass * 9.81;
    for (int c = 0; c < static_cast<int>(step.contacts.size()); ++c) {
      const Surface& s1 = scene.surfaces.get(step.contacts[c].contact.s1);
      const std::vector<Eigen::Vector3d> vertices = s1.vertices_L();
      for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
        VertexForce f;
        f.contact = c;
        f.vertex = v;
        f.point_W = data.T_WL[s1.link] * vertices[v];
        f.force_W = Eigen::Vector3d(0.0, 0.0, weight / 8.0);
        step.forces.push_back(f);
      }
    }
    plan.steps.push_back(step);
  }
  const std::string path = dir + "/humanoid_plan.json";
  write_plan(plan, scenario, path);
  return path;
}

// TALOS (STL meshes, several mirrored) as a floating robot, standing at the origin. From
// ../shared: tests that call it start with STANCEPLAN_REQUIRE_SHARED("robots/talos").
inline Scene talos_scene(Eigen::VectorXd* q) {
  UrdfOptions options;
  options.packages.directories = {talos_package_dir()};
  options.packages.use_ros_package_path = false;
  Entity entity;
  entity.name = "talos";
  entity.kind = EntityKind::FloatingRobot;
  entity.model = std::make_shared<const Model>(load_urdf(talos_urdf(), options));
  Scene scene;
  scene.system.add(entity);
  scene.surfaces = SurfaceSet(1);
  *q = scene.system.neutral_configuration();
  (*q)[2] = 1.08;
  return scene;
}

}  // namespace stanceplan::test
