#include "planner/io/scenario.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "planner/collision/srdf.h"
#include "planner/util/input_error.h"
#include "planner/util/text_file.h"

namespace stanceplan {
namespace fs = std::filesystem;
namespace {

const char* kFormat = "stanceplan/scenario@1";

class ScenarioReader {
 public:
  explicit ScenarioReader(const std::string& path) : path_(path) {
    dir_ = fs::absolute(fs::path(path)).parent_path();
  }

  Scenario read() {
    YAML::Node root = load();
    Scenario s;
    s.file = path_;
    expect_keys(root, "",
                {"format", "name", "description", "entities", "stances", "guide", "physics",
                 "weights", "collision", "search", "solver"});
    const YAML::Node format = root["format"];
    if (!format || !format.IsScalar() || format.Scalar() != kFormat)
      fail(format ? format : root, "format",
           std::string("expected \"") + kFormat + "\"" +
               (format && format.IsScalar() ? ", found \"" + format.Scalar() + "\"" : ""));
    s.name = root["name"] ? text(root["name"], "name") : fs::path(path_).stem().string();
    s.description = root["description"] ? text(root["description"], "description") : "";
    read_physics(root["physics"], s);
    read_collision(root["collision"], s);
    const YAML::Node entities = require(root, "entities", "");
    if (!entities.IsSequence() || entities.size() == 0)
      fail(entities, "entities", "expected a non-empty list");
    for (size_t i = 0; i < entities.size(); ++i)
      s.spec.entities.push_back(read_entity(entities[i], "entities[" + std::to_string(i) + "]"));
    for (const EntitySpec& e : s.spec.entities) srdf_files_.push_back(e.srdf);
    s.scene = build_scene(s.spec);
    s.initial_configuration = s.scene.system.neutral_configuration();
    for (size_t i = 0; i < entities.size(); ++i)
      if (entities[i]["configuration"])
        read_configuration(entities[i]["configuration"],
                           "entities[" + std::to_string(i) + "].configuration", int(i),
                           s.initial_configuration, s.scene);
    const YAML::Node stances = require(root, "stances", "");
    expect_keys(stances, "stances", {"initial", "goal"});
    s.initial_stance =
        read_stance(require(stances, "initial", "stances"), "stances.initial", s.scene);
    s.goal_stance = read_stance(require(stances, "goal", "stances"), "stances.goal", s.scene);
    require_support(stances["initial"], "stances.initial", s.initial_stance, s);
    require_support(stances["goal"], "stances.goal", s.goal_stance, s);
    read_guide(root["guide"], s);
    s.has_guide = bool(root["guide"]);
    read_weights(root["weights"], s);
    read_search(root["search"], s);
    read_solver(root["solver"], s);
    return s;
  }

 private:
  YAML::Node load() {
    try {
      return YAML::Load(read_text_file(path_));
    } catch (const YAML::Exception& e) {
      throw InputError(path_ + ":" + std::to_string(e.mark.line + 1) +
                       ": not valid YAML: " + e.msg);
    }
  }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& field,
                         const std::string& what) const {
    std::string message = path_;
    if (node.IsDefined() && node.Mark().line >= 0)
      message += ":" + std::to_string(node.Mark().line + 1);
    throw InputError(message + ": " + (field.empty() ? "" : field + ": ") + what);
  }

  static std::string join(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
  }

  YAML::Node require(const YAML::Node& parent, const std::string& key,
                     const std::string& parent_field) const {
    if (!parent.IsMap()) fail(parent, parent_field, "expected a mapping");
    const YAML::Node node = parent[key];
    if (!node) fail(parent, join(parent_field, key), "missing");
    return node;
  }

  // A mapping's key: a plain word (a list or mapping as a key is a fault of the file).
  std::string key_of(const YAML::Node& key, const std::string& field) const {
    if (!key.IsScalar())
      fail(key, field,
           "expected a field name, found a " + std::string(key.IsSequence() ? "list"
                                                           : key.IsMap()    ? "mapping"
                                                                            : "null"));
    return key.Scalar();
  }

  // Unknown keys are errors: a misspelt field must not be silently ignored.
  void expect_keys(const YAML::Node& node, const std::string& field,
                   std::initializer_list<const char*> keys) const {
    if (!node.IsMap()) fail(node, field, "expected a mapping");
    for (const auto& item : node) {
      const std::string key = key_of(item.first, field);
      if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; })) {
        std::string known;
        for (const char* k : keys) known += std::string(known.empty() ? "" : ", ") + k;
        fail(item.first, join(field, key), "unknown field (expected one of: " + known + ")");
      }
    }
  }

  std::string text(const YAML::Node& node, const std::string& field) const {
    if (!node.IsScalar()) fail(node, field, "expected a string");
    return node.Scalar();
  }

  double number(const YAML::Node& node, const std::string& field) const {
    if (!node.IsScalar()) fail(node, field, "expected a number");
    try {
      const double v = node.as<double>();
      if (!std::isfinite(v))
        fail(node, field, "expected a finite number, found \"" + node.Scalar() + "\"");
      return v;
    } catch (const YAML::Exception&) {
      fail(node, field, "expected a number, found \"" + node.Scalar() + "\"");
    }
  }

  double positive(const YAML::Node& node, const std::string& field) const {
    const double v = number(node, field);
    if (!(v > 0.0)) fail(node, field, "expected a number > 0, found " + node.Scalar());
    return v;
  }

  int integer(const YAML::Node& node, const std::string& field, int min) const {
    const double v = number(node, field);
    if (v != std::floor(v) || v < min || v > std::numeric_limits<int>::max())
      fail(node, field,
           "expected a whole number >= " + std::to_string(min) + ", found " + node.Scalar());
    return static_cast<int>(v);
  }

  bool boolean(const YAML::Node& node, const std::string& field) const {
    try {
      return node.as<bool>();
    } catch (const YAML::Exception&) {
      fail(node, field, "expected true or false");
    }
  }

  Eigen::VectorXd numbers(const YAML::Node& node, const std::string& field, int count,
                          const std::string& shape) const {
    if (!node.IsSequence() || int(node.size()) != count) fail(node, field, "expected " + shape);
    Eigen::VectorXd v(count);
    for (int i = 0; i < count; ++i) v[i] = number(node[i], field + "[" + std::to_string(i) + "]");
    return v;
  }

  std::string path_of(const YAML::Node& node, const std::string& field) const {
    const fs::path p(text(node, field));
    return (p.is_absolute() ? p : dir_ / p).lexically_normal().string();
  }

  Eigen::Quaterniond orientation(const YAML::Node& parent, const std::string& field,
                                 const char* wxyz_key, const char* rpy_key) const {
    if (parent[wxyz_key] && parent[rpy_key])
      fail(parent[rpy_key], join(field, rpy_key),
           std::string("give either ") + wxyz_key + " or " + rpy_key + ", not both");
    if (parent[wxyz_key]) {
      const Eigen::VectorXd w = numbers(parent[wxyz_key], join(field, wxyz_key), 4, "[w, x, y, z]");
      if (w.norm() < 1e-9)
        fail(parent[wxyz_key], join(field, wxyz_key), "a zero quaternion is no orientation");
      return Eigen::Quaterniond(w[0], w[1], w[2], w[3]).normalized();
    }
    if (parent[rpy_key]) {
      const Eigen::VectorXd r =
          numbers(parent[rpy_key], join(field, rpy_key), 3, "[roll, pitch, yaw] (rad)");
      return Eigen::AngleAxisd(r[2], Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(r[1], Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(r[0], Eigen::Vector3d::UnitX());
    }
    return Eigen::Quaterniond::Identity();
  }

  EntitySpec read_entity(const YAML::Node& node, const std::string& field) const {
    expect_keys(node, field,
                {"name", "kind", "urdf", "surfaces", "srdf", "package_paths", "base_pose",
                 "configuration"});
    EntitySpec e;
    e.name = text(require(node, "name", field), join(field, "name"));
    const YAML::Node kind = require(node, "kind", field);
    if (!parse_entity_kind(text(kind, join(field, "kind")), &e.kind))
      fail(kind, join(field, "kind"),
           "expected floating, fixed, object or environment, found \"" + kind.Scalar() + "\"");
    e.urdf = path_of(require(node, "urdf", field), join(field, "urdf"));
    if (node["surfaces"]) read_entity_surfaces(node["surfaces"], join(field, "surfaces"), e);
    if (node["srdf"]) e.srdf = path_of(node["srdf"], join(field, "srdf"));
    if (const YAML::Node paths = node["package_paths"]) {
      if (!paths.IsSequence())
        fail(paths, join(field, "package_paths"), "expected a list of folders");
      for (size_t i = 0; i < paths.size(); ++i)
        e.package_paths.push_back(
            path_of(paths[i], join(field, "package_paths[" + std::to_string(i) + "]")));
    }
    if (const YAML::Node pose = node["base_pose"]) {
      const std::string f = join(field, "base_pose");
      if (e.kind == EntityKind::FloatingRobot || e.kind == EntityKind::Object)
        fail(pose, f,
             "a floating entity's pose is its configuration (configuration.base_position)");
      expect_keys(pose, f, {"position", "orientation_wxyz", "rpy"});
      if (pose["position"])
        e.T_WB.translation() = numbers(pose["position"], join(f, "position"), 3, "[x, y, z]");
      e.T_WB.linear() = orientation(pose, f, "orientation_wxyz", "rpy").toRotationMatrix();
    }
    if (node["configuration"] && e.kind == EntityKind::Environment)
      fail(node["configuration"], join(field, "configuration"),
           "the environment has no configuration");
    return e;
  }

  // surfaces: a surface file, `auto`, or `{auto: {slope: 30, ...}}`: surfaces extracted from the
  // environment's collision geometry (planner/contact/affordances.h).
  void read_entity_surfaces(const YAML::Node& node, const std::string& field, EntitySpec& e) const {
    if (!(node.IsScalar() && node.Scalar() == "auto") && !node.IsMap()) {
      e.surfaces = path_of(node, field);
      return;
    }
    if (e.kind != EntityKind::Environment)
      fail(node, field,
           "auto surfaces are for environments only (entity \"" + e.name + "\" is " +
               to_string(e.kind) + "): give a surface file");
    AffordanceOptions options;
    if (node.IsMap()) {
      expect_keys(node, field, {"auto"});
      const YAML::Node o = require(node, "auto", field);
      const std::string f = join(field, "auto");
      if (!o.IsNull())
        expect_keys(o, f,
                    {"slope", "lean", "angle_tolerance", "offset_tolerance", "min_area", "inset"});
      auto read = [&](const char* key, double max, const char* unit, double* out) {
        if (o.IsNull() || !o[key]) return;
        *out = number(o[key], join(f, key));
        if (*out < 0.0 || *out > max)
          fail(o[key], join(f, key),
               std::string("expected a number from 0 to ") + (max > 1e9 ? "infinity" : "90") +
                   " (" + unit + "), found " + o[key].Scalar());
      };
      const double kNoMax = std::numeric_limits<double>::max();
      read("slope", 90.0, "degrees", &options.slope);
      read("lean", 90.0, "degrees", &options.lean);
      read("angle_tolerance", 90.0, "degrees", &options.angle_tolerance);
      read("offset_tolerance", kNoMax, "m", &options.offset_tolerance);
      read("min_area", kNoMax, "m^2", &options.min_area);
      read("inset", kNoMax, "m", &options.inset);
    }
    e.auto_surfaces = options;
  }

  // A (partial) configuration of entity e written into q: an SRDF group state first, then the
  // base pose and named joints, which override it.
  void read_configuration(const YAML::Node& node, const std::string& field, int e,
                          Eigen::VectorXd& q, const Scene& scene,
                          Eigen::VectorXd* stated = nullptr) const {
    expect_keys(node, field,
                {"srdf_state", "base_position", "base_orientation_wxyz", "base_rpy", "joints"});
    const System& system = scene.system;
    const Entity& entity = system.entity(e);
    const int offset = system.offset(e);
    if (node["srdf_state"])
      read_srdf_state(node["srdf_state"], join(field, "srdf_state"), e, q, scene, stated);
    if (!entity.floating() &&
        (node["base_position"] || node["base_orientation_wxyz"] || node["base_rpy"]))
      fail(node, field,
           "entity \"" + entity.name + "\" is not floating: give its base_pose instead");
    if (node["base_position"]) {
      q.segment<3>(offset) =
          numbers(node["base_position"], join(field, "base_position"), 3, "[x, y, z]");
      if (stated) stated->segment<3>(offset).setOnes();
    }
    if (node["base_orientation_wxyz"] || node["base_rpy"]) {
      const Eigen::Quaterniond quat = orientation(node, field, "base_orientation_wxyz", "base_rpy");
      q.segment<4>(offset + 3) = Eigen::Vector4d(quat.w(), quat.x(), quat.y(), quat.z());
      if (stated) stated->segment<4>(offset + 3).setOnes();
    }
    const YAML::Node joints = node["joints"];
    if (!joints) return;
    if (!joints.IsMap())
      fail(joints, join(field, "joints"), "expected a mapping joint name: value (rad or m)");
    const Model& model = *entity.model;
    for (const auto& item : joints) {
      const std::string name = key_of(item.first, join(field, "joints"));
      const std::string f = join(field, "joints." + name);
      const int dof = model.find_dof(name);
      if (dof < 0) {
        const int j = model.find_joint(name);
        fail(item.first, f,
             j < 0 ? "model \"" + model.name + "\" has no joint \"" + name + "\""
                   : "joint \"" + name + "\" is not an independent joint (fixed or mimic)");
      }
      const double value = number(item.second, f);
      const Joint& joint = model.joints[model.dof_joints[dof]];
      if (joint.has_position_limits && (value < joint.lower - 1e-9 || value > joint.upper + 1e-9))
        fail(item.second, f,
             std::to_string(value) + " is outside the joint's limits [" +
                 std::to_string(joint.lower) + ", " + std::to_string(joint.upper) + "]");
      q[offset + entity.first_dof() + dof] = value;
      if (stated) (*stated)[offset + entity.first_dof() + dof] = 1.0;
    }
  }

  // srdf_state: NAME, every <group_state name="NAME"> of the entity's SRDF (several when the name
  // recurs for other groups), in file order.
  void read_srdf_state(const YAML::Node& node, const std::string& field, int e, Eigen::VectorXd& q,
                       const Scene& scene, Eigen::VectorXd* stated) const {
    const std::string name = text(node, field);
    const Entity& entity = scene.system.entity(e);
    const std::string& srdf = srdf_files_[e];
    if (srdf.empty())
      fail(node, field,
           "entity \"" + entity.name + "\" has no srdf (give its srdf: FILE to use a group state)");
    const SrdfStates file = load_srdf_states(srdf);
    bool found = false;
    std::vector<std::string> known;
    for (const SrdfGroupState& state : file.states) {
      if (std::find(known.begin(), known.end(), state.name) == known.end())
        known.push_back(state.name);
      if (state.name != name) continue;
      found = true;
      for (const SrdfJointValue& joint : state.joints)
        apply_state_joint(node, field, srdf, state, joint, file, e, q, scene, stated);
    }
    if (!found) {
      std::string list;
      for (const std::string& k : known) {
        list += list.empty() ? " " : ", ";
        list += k;
      }
      fail(node, field,
           "no group_state \"" + name + "\" in " + srdf +
               " (it has:" + (known.empty() ? std::string(" none") : list) + ")");
    }
  }

  // One joint of an SRDF group state written into q. A joint the URDF lacks is the floating base
  // when the SRDF declares it a floating <virtual_joint> or it is Pinocchio's "root_joint" (as in
  // the example-robot-data models): x y z qx qy qz qw, left out for an entity that is not floating
  // (its base_pose places it).
  void apply_state_joint(const YAML::Node& node, const std::string& field, const std::string& srdf,
                         const SrdfGroupState& state, const SrdfJointValue& joint,
                         const SrdfStates& file, int e, Eigen::VectorXd& q, const Scene& scene,
                         Eigen::VectorXd* stated) const {
    const Entity& entity = scene.system.entity(e);
    const Model& model = *entity.model;
    const int offset = scene.system.offset(e);
    const std::string where = srdf + ":" + std::to_string(joint.line) + ": group_state \"" +
                              state.name + "\": joint \"" + joint.joint + "\": ";
    const int n = static_cast<int>(joint.values.size());
    const int j = model.find_joint(joint.joint);
    if (j < 0 && is_floating_base(joint.joint, file)) {
      if (n != 7)
        fail(node, field,
             where + "expected 7 values for the floating base (x y z qx qy qz qw), found " +
                 std::to_string(n));
      if (!entity.floating()) return;
      const Eigen::Quaterniond quat(joint.values[6], joint.values[3], joint.values[4],
                                    joint.values[5]);
      if (quat.norm() < 1e-9) fail(node, field, where + "a zero quaternion is no orientation");
      q.segment<3>(offset) = Eigen::Vector3d(joint.values[0], joint.values[1], joint.values[2]);
      const Eigen::Quaterniond unit = quat.normalized();
      q.segment<4>(offset + 3) = Eigen::Vector4d(unit.w(), unit.x(), unit.y(), unit.z());
      if (stated) stated->segment<7>(offset).setOnes();
      return;
    }
    if (j < 0)
      fail(node, field,
           where + "model \"" + model.name + "\" (" + model.source_file + ") has no such joint");
    const int dof = model.find_dof(joint.joint);
    if (dof < 0)
      fail(node, field, where + "not an independent joint of the model (fixed or mimic)");
    if (n != 1)
      fail(node, field,
           where + "expected one value (the joint has one degree of freedom), found " +
               std::to_string(n) +
               " (multi-dof joints other than the floating base are not "
               "supported)");
    const double value = joint.values[0];
    const Joint& model_joint = model.joints[j];
    if (model_joint.has_position_limits &&
        (value < model_joint.lower - 1e-9 || value > model_joint.upper + 1e-9))
      fail(node, field,
           where + std::to_string(value) + " is outside the joint's limits [" +
               std::to_string(model_joint.lower) + ", " + std::to_string(model_joint.upper) + "]");
    q[offset + entity.first_dof() + dof] = value;
    if (stated) (*stated)[offset + entity.first_dof() + dof] = 1.0;
  }

  static bool is_floating_base(const std::string& joint, const SrdfStates& file) {
    const auto& declared = file.floating_joints;
    return joint == "root_joint" ||
           std::find(declared.begin(), declared.end(), joint) != declared.end();
  }

  SurfaceRef surface(const YAML::Node& node, const std::string& field, const Scene& scene) const {
    const std::string id = text(node, field);
    if (auto ref = scene.surfaces.find(scene.system, id)) return *ref;
    const size_t slash = id.find('/');
    const int e = slash == std::string::npos ? -1 : scene.system.find_entity(id.substr(0, slash));
    if (e < 0)
      fail(node, field,
           "no surface \"" + id + "\" (expected \"entity/surface\" with a known entity)");
    std::string known;
    for (const Surface& s : scene.surfaces.of(e)) known += (known.empty() ? "" : ", ") + s.name;
    fail(node, field,
         "no surface \"" + id + "\" (entity \"" + scene.system.entity(e).name +
             "\" has: " + (known.empty() ? "no surfaces" : known) + ")");
  }

  // A point surface (a sphere at a point of a link) touches a polygon: it is s1, never s2.
  static std::string point_as_s2(const Scene& scene, const Contact& c, const Surface& s1) {
    return "contact " + scene.surfaces.id(scene.system, c.s1) + " - " +
           scene.surfaces.id(scene.system, c.s2) + ": s2 \"" +
           scene.surfaces.id(scene.system, c.s2) +
           "\" is a point surface, which can only be the s1 of a contact (s2 must be a polygon" +
           (s1.is_point() ? ": two points cannot touch)" : "; swap s1 and s2)");
  }

  std::vector<StanceContact> read_stance(const YAML::Node& node, const std::string& field,
                                         const Scene& scene) const {
    if (!node.IsSequence()) fail(node, field, "expected a list of contacts {s1, s2}");
    std::vector<StanceContact> out;
    std::vector<SurfaceRef> smaller, larger;
    for (size_t i = 0; i < node.size(); ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      const YAML::Node c = node[i];
      expect_keys(c, f, {"s1", "s2", "bilateral", "fixed", "placement"});
      StanceContact sc;
      sc.field = f;
      sc.line = c.Mark().line >= 0 ? c.Mark().line + 1 : 0;
      sc.contact.s1 = surface(require(c, "s1", f), f + ".s1", scene);
      sc.contact.s2 = surface(require(c, "s2", f), f + ".s2", scene);
      if (c["bilateral"]) sc.contact.bilateral = boolean(c["bilateral"], f + ".bilateral");
      if (c["fixed"]) sc.contact.fixed = boolean(c["fixed"], f + ".fixed");
      if (c["placement"]) {
        const Eigen::VectorXd p =
            numbers(c["placement"], f + ".placement", 3, "[x, y, theta] of s1 in s2's frame");
        sc.placement = Placement{p[0], p[1], p[2]};
      }
      const Surface& s1 = scene.surfaces.get(sc.contact.s1);
      const Surface& s2 = scene.surfaces.get(sc.contact.s2);
      if (sc.contact.s1.entity == sc.contact.s2.entity && s1.link == s2.link)
        fail(c, f, "s1 and s2 are on the same link \"" + s1.link_name + "\"");
      if (s2.is_point()) fail(c["s2"], f + ".s2", point_as_s2(scene, sc.contact, s1));
      const auto in = [](const std::vector<SurfaceRef>& l, SurfaceRef r) {
        return std::find(l.begin(), l.end(), r) != l.end();
      };
      if (in(smaller, sc.contact.s1) || in(larger, sc.contact.s1))
        fail(c["s1"], f + ".s1",
             "surface \"" + scene.surfaces.id(scene.system, sc.contact.s1) +
                 "\" is already in a contact of this stance");
      if (in(smaller, sc.contact.s2))
        fail(c["s2"], f + ".s2",
             "surface \"" + scene.surfaces.id(scene.system, sc.contact.s2) +
                 "\" is already the smaller surface of a contact of this stance");
      smaller.push_back(sc.contact.s1);
      larger.push_back(sc.contact.s2);
      out.push_back(sc);
    }
    return out;
  }

  // Under gravity a floating entity needs at least one contact to be in static equilibrium (E16):
  // an empty stance could never be realised, so it is a fault of the file, not a search failure.
  void require_support(const YAML::Node& node, const std::string& field,
                       const std::vector<StanceContact>& stance, const Scenario& s) const {
    if (!stance.empty() || s.spec.gravity.norm() == 0.0) return;
    for (const Entity& entity : s.scene.system.entities())
      if (entity.floating())
        fail(node, field,
             "expected at least one contact, found none: the floating entity \"" + entity.name +
                 "\" cannot be in static equilibrium under gravity without one");
  }

 public:
  // A guide given as text (read_guide_section).
  void read_guide_text(const std::string& text, Scenario& s) {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
      throw InputError(path_ + ":" + std::to_string(e.mark.line + 1) +
                       ": not valid YAML: " + e.msg);
    }
    expect_keys(root, "", {"guide"});
    s.milestones.clear(), s.milestone_masks.clear(), s.milestone_tolerances.clear();
    s.milestone_contact_pairs.clear();
    read_guide(require(root, "guide", ""), s);
  }

 private:
  // Milestones are partial: what a milestone leaves out keeps its value from the previous one
  // (the first continues the initial configuration).
  void read_guide(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    if (!node.IsSequence()) fail(node, "guide", "expected a list of milestones");
    Eigen::VectorXd q = s.initial_configuration;
    for (size_t i = 0; i < node.size(); ++i) {
      const std::string f = "guide[" + std::to_string(i) + "]";
      if (!node[i].IsMap()) fail(node[i], f, "expected a mapping entity name: configuration");
      double tolerance = 0.0;
      std::vector<std::pair<std::string, std::string>> pairs;
      Eigen::VectorXd stated = Eigen::VectorXd::Zero(q.size());
      for (const auto& item : node[i]) {
        const std::string name = key_of(item.first, f);
        if (name == "tolerance") {
          tolerance = positive(item.second, f + ".tolerance");
          continue;
        }
        if (name == "contacts") {
          read_patterns(item.second, f + ".contacts", &pairs);
          continue;
        }
        const int e = s.scene.system.find_entity(name);
        if (e < 0) fail(item.first, f + "." + name, "no entity \"" + name + "\"");
        read_configuration(item.second, f + "." + name, e, q, s.scene, &stated);
      }
      s.milestones.push_back(q);
      s.milestone_masks.push_back(stated);
      s.milestone_tolerances.push_back(tolerance);
      s.milestone_contact_pairs.push_back(std::move(pairs));
    }
  }

  void read_physics(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    expect_keys(node, "physics", {"gravity", "friction", "cone_generators"});
    if (node["gravity"])
      s.spec.gravity = numbers(node["gravity"], "physics.gravity", 3, "[gx, gy, gz] (m/s^2)");
    if (node["friction"]) s.solver.friction = positive(node["friction"], "physics.friction");
    if (node["cone_generators"])
      s.solver.cone_generators = integer(node["cone_generators"], "physics.cone_generators", 3);
  }

  void read_weights(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    expect_keys(node, "weights", {"configuration", "force", "torque", "placement"});
    auto weight = [&](const char* key, double* out) {
      if (!node[key]) return;
      *out = number(node[key], std::string("weights.") + key);
      if (*out < 0) fail(node[key], std::string("weights.") + key, "expected a weight >= 0");
    };
    weight("configuration", &s.solver.w_configuration);
    weight("force", &s.solver.w_force);
    weight("torque", &s.solver.w_torque);
    weight("placement", &s.solver.w_placement);
  }

  void read_collision(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    expect_keys(node, "collision", {"enabled", "margin", "active_distance", "ignore"});
    if (node["enabled"]) s.spec.collision = boolean(node["enabled"], "collision.enabled");
    if (node["margin"]) s.solver.collision_margin = number(node["margin"], "collision.margin");
    if (node["active_distance"])
      s.solver.collision_active_distance =
          positive(node["active_distance"], "collision.active_distance");
    if (const YAML::Node ignore = node["ignore"]) {
      if (!ignore.IsSequence())
        fail(ignore, "collision.ignore", "expected a list of [entity/link, entity/link]");
      for (size_t i = 0; i < ignore.size(); ++i) {
        const std::string f = "collision.ignore[" + std::to_string(i) + "]";
        if (!ignore[i].IsSequence() || ignore[i].size() != 2)
          fail(ignore[i], f, "expected [entity/link, entity/link]");
        LinkName names[2];
        for (int k = 0; k < 2; ++k) {
          const std::string id = text(ignore[i][k], f);
          const size_t slash = id.find('/');
          if (slash == std::string::npos)
            fail(ignore[i][k], f, "expected \"entity/link\", found \"" + id + "\"");
          names[k] = {id.substr(0, slash), id.substr(slash + 1)};
        }
        s.spec.ignored_pairs.emplace_back(names[0], names[1]);
      }
    }
  }

  void read_search(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    expect_keys(node, "search",
                {"max_nodes",
                 "time_limit",
                 "milestone_tolerance",
                 "threads",
                 "contact_reach",
                 "self_contacts",
                 "placement_tolerance",
                 "orientation_tolerance",
                 "stance_weight",
                 "max_retries",
                 "contact_pairs",
                 "last_contacts",
                 "min_contacts",
                 "defer_repeated_failures",
                 "defer_predicted_loops",
                 "defer_unbalanced_removals",
                 "expansion_batch",
                 "order_candidates",
                 "progress_budget",
                 "guide_seed",
                 "guide_spacing",
                 "guide_max_checks",
                 "guide_time_limit",
                 "batch_margin",
                 "skip_unreached_milestones",
                 "advance_past_milestones"});
    if (node["contact_pairs"])
      read_patterns(node["contact_pairs"], "search.contact_pairs", &s.search.contact_pairs);
    if (node["last_contacts"])
      read_patterns(node["last_contacts"], "search.last_contacts", &s.search.last_contacts);
    if (node["contact_reach"])
      s.search.contact_reach = positive(node["contact_reach"], "search.contact_reach");
    if (node["self_contacts"])
      s.search.self_contacts = boolean(node["self_contacts"], "search.self_contacts");
    if (node["min_contacts"])
      s.search.min_contacts = integer(node["min_contacts"], "search.min_contacts", 1);
    if (node["placement_tolerance"])
      s.search.placement_tolerance =
          positive(node["placement_tolerance"], "search.placement_tolerance");
    if (node["orientation_tolerance"])
      s.search.orientation_tolerance =
          positive(node["orientation_tolerance"], "search.orientation_tolerance");
    if (node["stance_weight"])
      s.search.stance_weight = number(node["stance_weight"], "search.stance_weight");
    if (node["max_retries"])
      s.search.max_retries = integer(node["max_retries"], "search.max_retries", 0);
    if (node["defer_repeated_failures"])
      s.search.defer_repeated_failures =
          boolean(node["defer_repeated_failures"], "search.defer_repeated_failures");
    if (node["defer_predicted_loops"])
      s.search.defer_predicted_loops =
          boolean(node["defer_predicted_loops"], "search.defer_predicted_loops");
    if (node["defer_unbalanced_removals"])
      s.search.defer_unbalanced_removals =
          boolean(node["defer_unbalanced_removals"], "search.defer_unbalanced_removals");
    if (node["advance_past_milestones"])
      s.search.advance_past_milestones =
          boolean(node["advance_past_milestones"], "search.advance_past_milestones");
    if (node["skip_unreached_milestones"])
      s.search.skip_unreached_milestones =
          boolean(node["skip_unreached_milestones"], "search.skip_unreached_milestones");
    if (node["expansion_batch"])
      s.search.expansion_batch = integer(node["expansion_batch"], "search.expansion_batch", 0);
    if (node["batch_margin"])
      s.search.batch_margin = number(node["batch_margin"], "search.batch_margin");
    if (node["order_candidates"])
      s.search.order_candidates = boolean(node["order_candidates"], "search.order_candidates");
    if (node["progress_budget"])
      s.search.progress_budget = integer(node["progress_budget"], "search.progress_budget", 0);
    if (node["max_nodes"]) s.search.max_nodes = integer(node["max_nodes"], "search.max_nodes", 1);
    if (node["time_limit"])
      s.search.time_limit_s = positive(node["time_limit"], "search.time_limit");
    if (node["milestone_tolerance"])
      s.search.milestone_tolerance =
          positive(node["milestone_tolerance"], "search.milestone_tolerance");
    if (node["threads"]) s.search.threads = integer(node["threads"], "search.threads", 0);
    if (node["guide_seed"])
      s.guide.seed = std::uint32_t(integer(node["guide_seed"], "search.guide_seed", 0));
    if (node["guide_spacing"])
      s.guide.spacing = positive(node["guide_spacing"], "search.guide_spacing");
    if (node["guide_max_checks"])
      s.guide.max_checks = integer(node["guide_max_checks"], "search.guide_max_checks", 1);
    // The old wall-clock budget: no number of seconds is a number of checks on every machine, so
    // the file is refused with the field to write instead of read with a guessed budget.
    if (node["guide_time_limit"])
      fail(node["guide_time_limit"], "search.guide_time_limit",
           "replaced by search.guide_max_checks, the guide's budget in validity checks (default " +
               std::to_string(GuideOptions{}.max_checks) +
               "): seconds gave different guides on different machines");
    s.guide.contact_pairs = s.search.contact_pairs;
  }

  void read_patterns(const YAML::Node& pairs, const std::string& field,
                     std::vector<std::pair<std::string, std::string>>* out) const {
    if (!pairs.IsSequence()) fail(pairs, field, "expected a list of [s1 pattern, s2 pattern]");
    for (size_t i = 0; i < pairs.size(); ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      if (!pairs[i].IsSequence() || pairs[i].size() != 2)
        fail(pairs[i], f, "expected [s1 pattern, s2 pattern]");
      out->emplace_back(text(pairs[i][0], f), text(pairs[i][1], f));
    }
  }

  void read_solver(const YAML::Node& node, Scenario& s) const {
    if (!node) return;
    expect_keys(node, "solver", {"max_iterations", "tolerance", "stall_after"});
    if (node["max_iterations"])
      s.solver.max_iterations = integer(node["max_iterations"], "solver.max_iterations", 1);
    if (node["stall_after"])
      s.solver.stall.after = integer(node["stall_after"], "solver.stall_after", 0);
  }

  std::string path_;
  fs::path dir_;
  std::vector<std::string> srdf_files_;  // per entity, "" when it has none
};

}  // namespace

Scenario load_scenario(const std::string& path) {
  Scenario s = ScenarioReader(path).read();
  s.scene.gravity = s.spec.gravity;
  return s;
}

void read_guide_section(Scenario& scenario, const std::string& text, const std::string& origin) {
  ScenarioReader(origin).read_guide_text(text, scenario);
}

}  // namespace stanceplan
