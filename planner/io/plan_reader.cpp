#include "planner/io/plan_reader.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "planner/util/input_error.h"
#include "planner/util/text_file.h"

namespace stanceplan {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;

class PlanReader {
 public:
  PlanReader(const std::string& path, const PlanReadOptions& options)
      : path_(path), options_(options) {
    dir_ = fs::absolute(fs::path(path)).parent_path();
  }

  LoadedPlan read() {
    const json root = load();
    LoadedPlan out;
    out.file = path_;
    object(root, "");
    const std::string format = string(root, "format", "");
    if (format != "stanceplan/plan@1" && format != "stanceplan/plan@2")
      fail("format",
           "expected \"stanceplan/plan@1\" or \"stanceplan/plan@2\", found \"" + format + "\"");
    if (root.contains("partial"))
      out.plan.partial = string(member(root, "partial", ""), "reason", "partial");
    if (root.contains("failed"))
      out.plan.failed = string(member(root, "failed", ""), "reason", "failed");
    out.scenario = root.contains("scenario") && root["scenario"].is_string()
                       ? root["scenario"].get<std::string>()
                       : "";
    out.spec.gravity = vector3(member(root, "gravity", ""), "gravity");
    out.friction = number(member(root, "friction", ""), "friction");
    if (root.contains("cone_generators")) {
      const double k = number(root["cone_generators"], "cone_generators");
      if (k != std::floor(k) || k < 3 || k > 64)
        fail("cone_generators",
             "expected a whole number from 3 to 64, found " + root["cone_generators"].dump());
      out.cone_generators = int(k);
    }
    read_entities(member(root, "entities", ""), out.spec);
    read_ignored(root, out);
    out.spec.collision = options_.build_collision;
    out.spec.ignored_pairs = out.ignored_pairs;
    // Surfaces come from the plan itself (the checker must not depend on the surface files).
    std::vector<EntitySpec> without_surface_files = out.spec.entities;
    for (EntitySpec& e : without_surface_files) e.surfaces.clear();
    SceneSpec build = out.spec;
    build.entities = without_surface_files;
    out.scene = build_scene(build);
    read_surfaces(member(root, "surfaces", ""), out.scene);
    const json& steps = member(root, "steps", "");
    if (!steps.is_array()) fail("steps", "expected an array");
    for (size_t i = 0; i < steps.size(); ++i) {
      const std::string f = "steps[" + std::to_string(i) + "]";
      out.plan.steps.push_back(read_step(steps[i], f, out.scene));
      if (steps[i].contains("motion")) {
        if (i == 0) fail(f + ".motion", "step 0 has no motion into it");
        out.plan.steps[i].motion = read_motion(steps[i]["motion"], f + ".motion", out.scene,
                                               out.plan.steps[i - 1].stance.contacts());
      }
    }
    if (root.contains("stats")) {
      const json& s = root["stats"];
      object(s, "stats");
      out.plan.stats.nodes_expanded = whole_number(s, "nodes_expanded", 0, "stats");
      out.plan.stats.solver_calls = whole_number(s, "solver_calls", 0, "stats");
      out.plan.stats.wall_time_s = optional_number(s, "wall_time_s", 0.0, "stats");
      out.plan.stats.threads = whole_number(s, "threads", 1, "stats");
    }
    return out;
  }

 private:
  json load() const {
    const std::string text = read_text_file(path_);
    try {
      return json::parse(text);
    } catch (const json::exception& e) {  // parse_error, and out_of_range for a number like 1e999
      throw InputError(path_ + ": not valid JSON: " + e.what());
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(path_ + ": " + (field.empty() ? "" : field + ": ") + what);
  }

  const json& member(const json& parent, const std::string& key, const std::string& field) const {
    object(parent, field);
    if (!parent.contains(key)) fail(field.empty() ? key : field + "." + key, "missing");
    return parent.at(key);
  }

  void object(const json& v, const std::string& field) const {
    if (!v.is_object()) fail(field, "expected an object, found " + found(v));
  }

  static std::string found(const json& v) {
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    return std::string(v.is_object() ? "an " : "a ") + v.type_name();
  }

  // Optional members (absent: the fallback); a member of the wrong type is an error, never ignored.
  bool flag(const json& parent, const std::string& key, bool fallback,
            const std::string& field) const {
    object(parent, field);
    if (!parent.contains(key)) return fallback;
    if (!parent[key].is_boolean())
      fail(field + "." + key, "expected true or false, found " + found(parent[key]));
    return parent[key].get<bool>();
  }

  double optional_number(const json& parent, const std::string& key, double fallback,
                         const std::string& field) const {
    return parent.contains(key) ? number(parent[key], field + "." + key) : fallback;
  }

  int whole_number(const json& parent, const std::string& key, int fallback,
                   const std::string& field) const {
    if (!parent.contains(key)) return fallback;
    const double d = number(parent[key], field + "." + key);
    if (d != std::floor(d) || d < 0 || d > 1e9)
      fail(field + "." + key, "expected a whole number >= 0, found " + parent[key].dump());
    return static_cast<int>(d);
  }

  std::string string(const json& parent, const std::string& key, const std::string& field) const {
    const json& v = member(parent, key, field);
    if (!v.is_string())
      fail(field.empty() ? key : field + "." + key, "expected a string, found " + found(v));
    return v.get<std::string>();
  }

  PostureStatus status(const std::string& name, const std::string& field) const {
    for (PostureStatus s : {PostureStatus::Solved, PostureStatus::Infeasible,
                            PostureStatus::IterationLimit, PostureStatus::NumericalFailure})
      if (name == to_string(s)) return s;
    fail(field, "expected solved, infeasible, iteration_limit or numerical_failure, found \"" +
                    name + "\"");
  }

  double number(const json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "expected a number, found " + found(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(field, "expected a finite number");
    return d;
  }

  Eigen::Vector3d vector3(const json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 3) fail(field, "expected [x, y, z], found " + found(v));
    return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
  }

  std::string path_of(const std::string& relative) const {
    const fs::path p(relative);
    return (p.is_absolute() ? p : dir_ / p).lexically_normal().string();
  }

  void read_entities(const json& list, SceneSpec& spec) const {
    if (!list.is_array() || list.empty()) fail("entities", "expected a non-empty array");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string f = "entities[" + std::to_string(i) + "]";
      const json& e = list[i];
      EntitySpec out;
      out.name = string(e, "name", f);
      const std::string kind = string(e, "kind", f);
      if (!parse_entity_kind(kind, &out.kind))
        fail(f + ".kind",
             "expected floating, fixed, object or environment, found \"" + kind + "\"");
      out.urdf = path_of(string(e, "urdf", f));
      // Informative (the surfaces come from "surfaces"), kept so that a plan rewritten names it.
      if (e.contains("surfaces_file")) out.surfaces = path_of(string(e, "surfaces_file", f));
      if (e.contains("package_paths")) {
        if (!e["package_paths"].is_array())
          fail(f + ".package_paths", "expected an array of folders");
        for (const json& p : e["package_paths"]) {
          if (!p.is_string()) fail(f + ".package_paths", "expected an array of folders");
          out.package_paths.push_back(path_of(p.get<std::string>()));
        }
      }
      if (e.contains("base_pose")) {
        const json& pose = e["base_pose"];
        out.T_WB.translation() =
            vector3(member(pose, "position", f + ".base_pose"), f + ".base_pose.position");
        const json& q = member(pose, "orientation_wxyz", f + ".base_pose");
        if (!q.is_array() || q.size() != 4)
          fail(f + ".base_pose.orientation_wxyz", "expected [w, x, y, z]");
        Eigen::Quaterniond quat(number(q[0], f), number(q[1], f), number(q[2], f), number(q[3], f));
        if (quat.norm() < 1e-9)
          fail(f + ".base_pose.orientation_wxyz", "a zero quaternion is no orientation");
        out.T_WB.linear() = quat.normalized().toRotationMatrix();
      }
      spec.entities.push_back(out);
    }
  }

  void read_ignored(const json& root, LoadedPlan& out) const {
    if (!root.contains("collision_pairs_ignored")) return;
    const json& list = root["collision_pairs_ignored"];
    if (!list.is_array())
      fail("collision_pairs_ignored", "expected an array of [entity/link, entity/link]");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string f = "collision_pairs_ignored[" + std::to_string(i) + "]";
      if (!list[i].is_array() || list[i].size() < 2 || !list[i][0].is_string() ||
          !list[i][1].is_string())
        fail(f, "expected [entity/link, entity/link]");
      LinkName names[2];
      for (int k = 0; k < 2; ++k) {
        const std::string id = list[i][k].get<std::string>();
        const size_t slash = id.find('/');
        if (slash == std::string::npos) fail(f, "expected \"entity/link\", found \"" + id + "\"");
        names[k] = {id.substr(0, slash), id.substr(slash + 1)};
      }
      out.ignored_pairs.emplace_back(names[0], names[1]);
    }
  }

  void read_surfaces(const json& list, Scene& scene) const {
    if (!list.is_array()) fail("surfaces", "expected an array");
    std::vector<std::vector<Surface>> per_entity(scene.system.num_entities());
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string f = "surfaces[" + std::to_string(i) + "]";
      const json& s = list[i];
      const std::string id = string(s, "id", f);
      const std::string entity_name = string(s, "entity", f);
      const int e = scene.system.find_entity(entity_name);
      if (e < 0) fail(f + ".entity", "no entity \"" + entity_name + "\"");
      if (id.rfind(entity_name + "/", 0) != 0)
        fail(f + ".id", "\"" + id + "\" does not start with \"" + entity_name + "/\"");
      const std::string link_name = string(s, "link", f);
      const int link = scene.system.entity(e).model->find_link(link_name);
      if (link < 0)
        fail(f + ".link", "model \"" + scene.system.entity(e).model->name + "\" has no link \"" +
                              link_name + "\"");
      if (s.contains("kind") && s["kind"] != "polygon") {
        if (s["kind"] != "point") fail(f + ".kind", "expected \"polygon\" or \"point\"");
        per_entity[e].push_back(
            point_surface(s, f, id.substr(entity_name.size() + 1), link, link_name));
        continue;
      }
      const json& rotation = member(s, "rotation", f);
      if (!rotation.is_array() || rotation.size() != 3)
        fail(f + ".rotation", "expected a 3x3 array of rows");
      Eigen::Matrix3d R;
      for (int r = 0; r < 3; ++r)
        R.row(r) = vector3(rotation[r], f + ".rotation[" + std::to_string(r) + "]");
      const json& vertices = member(s, "vertices", f);
      if (!vertices.is_array()) fail(f + ".vertices", "expected an array of [x, y, z]");
      std::vector<Eigen::Vector3d> v;
      for (size_t k = 0; k < vertices.size(); ++k)
        v.push_back(vector3(vertices[k], f + ".vertices[" + std::to_string(k) + "]"));
      Surface surface;
      std::string error;
      const Eigen::Vector3d x_axis = R.col(0), normal = R.col(2);
      // 1e-6 m: the plan writes vertices at full precision.
      if (!make_surface(id.substr(entity_name.size() + 1), link, link_name, v, normal, &x_axis,
                        &surface, &error, 1e-6))
        fail(f, error);
      per_entity[e].push_back(surface);
    }
    scene.surfaces = SurfaceSet(scene.system.num_entities());
    for (int e = 0; e < scene.system.num_entities(); ++e)
      scene.surfaces.set(e, std::move(per_entity[e]));
  }

  // A point surface (`"kind": "point"`): a sphere of `radius` at `point` in the link frame.
  Surface point_surface(const json& s, const std::string& f, const std::string& name, int link,
                        const std::string& link_name) const {
    const Eigen::Vector3d point = vector3(member(s, "point", f), f + ".point");
    const json& radius = member(s, "radius", f);
    if (!radius.is_number()) fail(f + ".radius", "expected a number (m)");
    Surface surface;
    std::string error;
    if (!make_point_surface(name, link, link_name, point, radius.get<double>(), &surface, &error))
      fail(f, error);
    return surface;
  }

  SurfaceRef surface_ref(const json& v, const std::string& field, const Scene& scene) const {
    if (!v.is_string()) fail(field, "expected a surface id");
    const auto ref = scene.surfaces.find(scene.system, v.get<std::string>());
    if (!ref) fail(field, "no surface \"" + v.get<std::string>() + "\" in the plan's surfaces");
    return *ref;
  }

  Contact contact(const json& c, const std::string& field, const Scene& scene) const {
    Contact out;
    out.s1 = surface_ref(member(c, "s1", field), field + ".s1", scene);
    out.s2 = surface_ref(member(c, "s2", field), field + ".s2", scene);
    return out;
  }

  Eigen::VectorXd configuration(const json& c, const std::string& field, const Scene& scene) const {
    const System& system = scene.system;
    Eigen::VectorXd q = system.neutral_configuration();
    for (int e = 0; e < system.num_entities(); ++e) {
      const Entity& entity = system.entity(e);
      if (entity.kind == EntityKind::Environment) continue;
      const std::string f = field + "." + entity.name;
      const json& ec = member(c, entity.name, field);
      const int offset = system.offset(e);
      if (entity.floating()) {
        q.segment<3>(offset) = vector3(member(ec, "base_position", f), f + ".base_position");
        const json& quat = member(ec, "base_orientation_wxyz", f);
        if (!quat.is_array() || quat.size() != 4)
          fail(f + ".base_orientation_wxyz", "expected [w, x, y, z]");
        for (int k = 0; k < 4; ++k)
          q[offset + 3 + k] = number(quat[k], f + ".base_orientation_wxyz");
      }
      const Model& model = *entity.model;
      const json& joints = model.num_dofs() > 0 ? member(ec, "joints", f) : json::object();
      object(joints, f + ".joints");
      for (int k = 0; k < model.num_dofs(); ++k) {
        const std::string& name = model.joints[model.dof_joints[k]].name;
        if (!joints.contains(name)) fail(f + ".joints", "missing joint \"" + name + "\"");
        q[offset + entity.first_dof() + k] = number(joints[name], f + ".joints." + name);
      }
    }
    return q;
  }

  // `contacts`: the contacts the forces may act through; VertexForce::contact indexes them.
  std::vector<VertexForce> read_forces(const json& forces, const std::string& field,
                                       const Scene& scene, const std::vector<Contact>& contacts,
                                       const std::string& which) const {
    if (!forces.is_array()) fail(field, "expected an array");
    std::vector<VertexForce> out;
    for (size_t i = 0; i < forces.size(); ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      const Contact c = contact(forces[i], f, scene);
      VertexForce vf;
      for (size_t k = 0; k < contacts.size(); ++k)
        if (contacts[k].same_surfaces(c)) vf.contact = int(k);
      if (vf.contact < 0) fail(f, "the force's contact is not among " + which);
      vf.point_W = vector3(member(forces[i], "point_world", f), f + ".point_world");
      vf.force_W = vector3(member(forces[i], "force_world", f), f + ".force_world");
      out.push_back(vf);
    }
    return out;
  }

  std::vector<Eigen::VectorXd> read_torques(const json& s, const std::string& field,
                                            const Scene& scene) const {
    std::vector<Eigen::VectorXd> out(scene.system.num_entities());
    if (!s.contains("torques")) return out;
    const json& torques = s["torques"];
    object(torques, field + ".torques");
    for (int e = 0; e < scene.system.num_entities(); ++e) {
      const Entity& entity = scene.system.entity(e);
      const Model& model = *entity.model;
      if (model.num_dofs() == 0 || !torques.contains(entity.name)) continue;
      out[e] = Eigen::VectorXd::Zero(model.num_dofs());
      for (int k = 0; k < model.num_dofs(); ++k) {
        const std::string& name = model.joints[model.dof_joints[k]].name;
        const std::string f = field + ".torques." + entity.name;
        object(torques[entity.name], f);
        if (!torques[entity.name].contains(name)) fail(f, "missing joint \"" + name + "\"");
        out[e][k] = number(torques[entity.name][name], f + "." + name);
      }
    }
    return out;
  }

  // A step's motion (format @2): samples holding the previous step's stance `held`.
  StepMotion read_motion(const json& m, const std::string& field, const Scene& scene,
                         const std::vector<Contact>& held) const {
    StepMotion motion;
    const std::string status = string(m, "status", field);
    if (!parse_motion_status(status, &motion.status))
      fail(field + ".status",
           "expected solved, projection_failed, spacing_not_reached or ends_disagree, found \"" +
               status + "\"");
    if (m.contains("message")) motion.message = string(m, "message", field);
    const json& samples = member(m, "samples", field);
    if (!samples.is_array()) fail(field + ".samples", "expected an array");
    for (size_t i = 0; i < samples.size(); ++i) {
      const std::string f = field + ".samples[" + std::to_string(i) + "]";
      MotionSample sample;
      sample.q = configuration(member(samples[i], "configuration", f), f + ".configuration", scene);
      sample.forces = read_forces(member(samples[i], "forces", f), f + ".forces", scene, held,
                                  "the previous step's stance");
      sample.torques = read_torques(samples[i], f, scene);
      motion.samples.push_back(std::move(sample));
    }
    return motion;
  }

  PlanStep read_step(const json& s, const std::string& field, const Scene& scene) const {
    PlanStep step;
    step.action = string(s, "action", field);
    if (step.action != "initial" && step.action != "add" && step.action != "remove")
      fail(field + ".action", "expected initial, add or remove, found \"" + step.action + "\"");
    if (s.contains("changed_contact") && !s["changed_contact"].is_null())
      step.changed = contact(s["changed_contact"], field + ".changed_contact", scene);
    const json& contacts = member(s, "contacts", field);
    if (!contacts.is_array()) fail(field + ".contacts", "expected an array");
    for (size_t i = 0; i < contacts.size(); ++i) {
      const std::string f = field + ".contacts[" + std::to_string(i) + "]";
      PlanContact pc{contact(contacts[i], f, scene), flag(contacts[i], "loaded", true, f)};
      pc.contact.bilateral = flag(contacts[i], "bilateral", false, f);
      pc.contact.fixed = flag(contacts[i], "fixed", false, f);
      step.contacts.push_back(pc);
    }
    std::vector<Contact> stance;
    const json& st = member(s, "stance", field);
    if (!st.is_array()) fail(field + ".stance", "expected an array");
    for (size_t i = 0; i < st.size(); ++i) {
      Contact c = contact(st[i], field + ".stance[" + std::to_string(i) + "]", scene);
      for (const PlanContact& pc : step.contacts)
        if (pc.contact.same_surfaces(c)) c = pc.contact;  // carry the bilateral / fixed tags
      stance.push_back(c);
    }
    step.stance = Stance(stance);
    step.q = configuration(member(s, "configuration", field), field + ".configuration", scene);
    std::vector<Contact> touched;
    for (const PlanContact& pc : step.contacts) touched.push_back(pc.contact);
    step.forces = read_forces(member(s, "forces", field), field + ".forces", scene, touched,
                              "the step's contacts");
    step.torques = read_torques(s, field, scene);
    if (s.contains("solver")) {
      const json& solver = s["solver"];
      object(solver, field + ".solver");
      step.iterations = whole_number(solver, "iterations", 0, field + ".solver");
      step.time_ms = optional_number(solver, "time_ms", 0.0, field + ".solver");
      step.objective = optional_number(solver, "objective", 0.0, field + ".solver");
      if (solver.contains("status"))
        step.status = status(string(solver, "status", field + ".solver"), field + ".solver.status");
    }
    return step;
  }

  std::string path_;
  PlanReadOptions options_;
  fs::path dir_;
};

}  // namespace

LoadedPlan read_plan(const std::string& path, const PlanReadOptions& options) {
  LoadedPlan out = PlanReader(path, options).read();
  out.scene.gravity = out.spec.gravity;
  return out;
}

}  // namespace stanceplan
