#include "planner/io/plan_writer.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "planner/util/atomic_file.h"

namespace stanceplan {
namespace fs = std::filesystem;
namespace {

using json = nlohmann::ordered_json;

json vec(const Eigen::Vector3d& v) {
  return json::array({v.x(), v.y(), v.z()});
}

std::string relative_to(const std::string& path, const fs::path& base) {
  const fs::path absolute = fs::absolute(path).lexically_normal();
  const fs::path relative = absolute.lexically_relative(base);
  return relative.empty() ? absolute.string() : relative.string();
}

json entity_json(const Scenario& s, int e, const fs::path& base) {
  const EntitySpec& spec = s.spec.entities[e];
  json out = {
      {"name", spec.name}, {"kind", to_string(spec.kind)}, {"urdf", relative_to(spec.urdf, base)}};
  json packages = json::array();
  for (const std::string& p : spec.package_paths) packages.push_back(relative_to(p, base));
  out["package_paths"] = packages;
  if (!spec.surfaces.empty()) out["surfaces_file"] = relative_to(spec.surfaces, base);
  if (!s.scene.system.entity(e).floating()) {
    const Eigen::Quaterniond quat(spec.T_WB.linear());
    out["base_pose"] = {{"position", vec(spec.T_WB.translation())},
                        {"orientation_wxyz", {quat.w(), quat.x(), quat.y(), quat.z()}}};
  }
  return out;
}

json surface_json(const Scene& scene, SurfaceRef ref) {
  const Surface& s = scene.surfaces.get(ref);
  if (s.is_point())  // a sphere at a point of the link: no frame, no polygon
    return {{"id", scene.surfaces.id(scene.system, ref)},
            {"entity", scene.system.entity(ref.entity).name},
            {"link", s.link_name},
            {"kind", "point"},
            {"point", vec(s.center_L())},
            {"radius", s.radius}};
  const Eigen::Matrix3d R = s.T_LS.linear();
  json rotation = json::array();
  for (int i = 0; i < 3; ++i) rotation.push_back({R(i, 0), R(i, 1), R(i, 2)});
  json vertices = json::array();
  for (const Eigen::Vector3d& v : s.vertices_L()) vertices.push_back(vec(v));
  return {{"id", scene.surfaces.id(scene.system, ref)},
          {"entity", scene.system.entity(ref.entity).name},
          {"link", s.link_name},
          {"origin", vec(s.T_LS.translation())},
          {"rotation", rotation},
          {"vertices", vertices}};
}

json pair_json(const Scene& scene, const Contact& c) {
  return {{"s1", scene.surfaces.id(scene.system, c.s1)},
          {"s2", scene.surfaces.id(scene.system, c.s2)}};
}

json configuration_json(const Scene& scene, const Eigen::VectorXd& q) {
  json out = json::object();
  for (int e = 0; e < scene.system.num_entities(); ++e) {
    const Entity& entity = scene.system.entity(e);
    if (entity.kind == EntityKind::Environment) continue;
    const int offset = scene.system.offset(e);
    json c = json::object();
    if (entity.floating()) {
      c["base_position"] = vec(q.segment<3>(offset));
      const Eigen::Vector4d quat = q.segment<4>(offset + 3);
      c["base_orientation_wxyz"] = {quat[0], quat[1], quat[2], quat[3]};
    }
    json joints = json::object();
    const Model& model = *entity.model;
    for (int k = 0; k < model.num_dofs(); ++k)
      joints[model.joints[model.dof_joints[k]].name] = q[offset + entity.first_dof() + k];
    c["joints"] = joints;
    out[entity.name] = c;
  }
  return out;
}

// `contacts`: what VertexForce::contact indexes (a step's touched contacts, or the stance a
// motion holds).
json forces_json(const Scene& scene, const std::vector<Contact>& contacts,
                 const std::vector<VertexForce>& forces) {
  json out = json::array();
  for (const VertexForce& f : forces) {
    json j = pair_json(scene, contacts[f.contact]);
    j["point_world"] = vec(f.point_W);
    j["force_world"] = vec(f.force_W);
    out.push_back(j);
  }
  return out;
}

json torques_json(const Scene& scene, const std::vector<Eigen::VectorXd>& torques) {
  json out = json::object();
  for (int e = 0; e < scene.system.num_entities(); ++e) {
    const Model& model = *scene.system.entity(e).model;
    if (model.num_dofs() == 0 || e >= int(torques.size()) || torques[e].size() == 0) continue;
    json t = json::object();
    for (int k = 0; k < model.num_dofs(); ++k)
      t[model.joints[model.dof_joints[k]].name] = torques[e][k];
    out[scene.system.entity(e).name] = t;
  }
  return out;
}

// The motion into a step: samples holding the previous step's stance, every contact loaded.
json motion_json(const Scene& scene, const StepMotion& motion, const Stance& held) {
  json samples = json::array();
  for (const MotionSample& s : motion.samples)
    samples.push_back({{"configuration", configuration_json(scene, s.q)},
                       {"forces", forces_json(scene, held.contacts(), s.forces)},
                       {"torques", torques_json(scene, s.torques)}});
  json out = {{"status", to_string(motion.status)}};
  if (!motion.message.empty()) out["message"] = motion.message;
  out["samples"] = samples;
  return out;
}

json step_json(const Scene& scene, const PlanStep& step, int index, const PlanStep* previous) {
  json contacts = json::array();
  for (const PlanContact& c : step.contacts) {
    json j = pair_json(scene, c.contact);
    j["bilateral"] = c.contact.bilateral;
    j["fixed"] = c.contact.fixed;
    j["loaded"] = c.loaded;
    contacts.push_back(j);
  }
  json stance = json::array();
  for (const Contact& c : step.stance.contacts()) stance.push_back(pair_json(scene, c));
  std::vector<Contact> touched;
  for (const PlanContact& c : step.contacts) touched.push_back(c.contact);
  json out = {{"index", index},
              {"action", step.action},
              {"changed_contact", step.changed ? pair_json(scene, *step.changed) : json(nullptr)},
              {"contacts", contacts},
              {"stance", stance},
              {"configuration", configuration_json(scene, step.q)},
              {"forces", forces_json(scene, touched, step.forces)},
              {"torques", torques_json(scene, step.torques)},
              {"solver",
               {{"status", to_string(step.status)},
                {"iterations", step.iterations},
                {"time_ms", step.time_ms},
                {"objective", step.objective}}}};
  if (step.motion && previous) out["motion"] = motion_json(scene, *step.motion, previous->stance);
  return out;
}

json ignored_pairs_json(const Scene& scene) {
  json out = json::array();
  if (!scene.collision) return out;
  for (const ExcludedPair& p : scene.collision->excluded_pairs()) {
    const auto name = [&](int entity, int link) {
      return scene.system.entity(entity).name + "/" +
             scene.system.entity(entity).model->links[link].name;
    };
    out.push_back({name(p.entity_a, p.link_a), name(p.entity_b, p.link_b)});
  }
  return out;
}

// Extra field, same order as collision_pairs_ignored: why each pair is not checked.
json ignored_reasons_json(const Scene& scene) {
  json out = json::array();
  if (scene.collision)
    for (const ExcludedPair& p : scene.collision->excluded_pairs()) out.push_back(p.reason);
  return out;
}

}  // namespace

std::string plan_to_json(const Plan& plan, const Scenario& s, const std::string& plan_path) {
  const fs::path base = fs::absolute(plan_path).parent_path();
  json out;
  // @2 adds the steps' motions; a plan without one stays readable by @1 readers.
  const bool motion = std::any_of(plan.steps.begin(), plan.steps.end(),
                                  [](const PlanStep& step) { return step.motion.has_value(); });
  out["format"] = motion ? "stanceplan/plan@2" : "stanceplan/plan@1";
  if (!plan.partial.empty()) out["partial"] = {{"reaches_goal", false}, {"reason", plan.partial}};
  if (!plan.failed.empty()) out["failed"] = {{"reason", plan.failed}};
  out["scenario"] = relative_to(s.file, base);
  out["gravity"] = vec(s.scene.gravity);
  out["friction"] = s.solver.friction;
  out["cone_generators"] = s.solver.cone_generators;
  json entities = json::array();
  for (int e = 0; e < s.scene.system.num_entities(); ++e)
    entities.push_back(entity_json(s, e, base));
  out["entities"] = entities;
  std::set<SurfaceRef> used;
  for (const PlanStep& step : plan.steps)
    for (const PlanContact& c : step.contacts) used.insert({c.contact.s1, c.contact.s2});
  // Every surface that appears in any contact of the plan.
  json surfaces = json::array();
  for (SurfaceRef ref : used) surfaces.push_back(surface_json(s.scene, ref));
  out["surfaces"] = surfaces;
  out["collision_pairs_ignored"] = ignored_pairs_json(s.scene);
  out["collision_pairs_ignored_reasons"] = ignored_reasons_json(s.scene);
  json steps = json::array();
  for (size_t i = 0; i < plan.steps.size(); ++i)
    steps.push_back(
        step_json(s.scene, plan.steps[i], int(i), i > 0 ? &plan.steps[i - 1] : nullptr));
  out["steps"] = steps;
  out["stats"] = {{"nodes_expanded", plan.stats.nodes_expanded},
                  {"solver_calls", plan.stats.solver_calls},
                  {"wall_time_s", plan.stats.wall_time_s},
                  {"threads", plan.stats.threads}};
  return out.dump(1);
}

void write_plan(const Plan& plan, const Scenario& scenario, const std::string& plan_path) {
  write_file_atomically(plan_path, plan_to_json(plan, scenario, plan_path) + "\n");
}

}  // namespace stanceplan
