#include "app/inspect_command.h"

#include <iomanip>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/inspect_figure.h"
#include "planner/collision/collision_matrix.h"
#include "planner/collision/collision_model.h"
#include "planner/contact/affordances.h"
#include "planner/contact/surface_file.h"
#include "planner/model/entity.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/atomic_file.h"

namespace stanceplan::app {
namespace {

using nlohmann::json;

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::Fixed:
      return "fixed";
    case JointType::Revolute:
      return "revolute";
    case JointType::Continuous:
      return "continuous";
    case JointType::Prismatic:
      return "prismatic";
  }
  return "?";
}

const char* shape_name(ShapeType type) {
  switch (type) {
    case ShapeType::Box:
      return "box";
    case ShapeType::Cylinder:
      return "cylinder";
    case ShapeType::Sphere:
      return "sphere";
    case ShapeType::Mesh:
      return "mesh";
  }
  return "?";
}

EntityKind decide_kind(const InspectOptions& options, const Model& model) {
  EntityKind kind = EntityKind::FixedRobot;
  if (options.kind == "auto") return model.num_links() == 1 ? EntityKind::Object : kind;
  parse_entity_kind(options.kind, &kind);  // validated by the CLI
  return kind;
}

json vector_json(const Eigen::Vector3d& v) {
  return json::array({v.x(), v.y(), v.z()});
}

json describe(const Model& model, EntityKind kind, const std::vector<Surface>& surfaces) {
  json out;
  out["name"] = model.name;
  out["file"] = model.source_file;
  out["kind"] = to_string(kind);
  out["floating"] = kind == EntityKind::FloatingRobot || kind == EntityKind::Object;
  out["dof"] = model.num_dofs();
  out["mass"] = model.total_mass;
  json joints = json::array();
  for (const Joint& joint : model.joints) {
    if (!joint.movable()) continue;
    json j = {{"name", joint.name},
              {"type", joint_type_name(joint.type)},
              {"lower", joint.has_position_limits ? json(joint.lower) : json(nullptr)},
              {"upper", joint.has_position_limits ? json(joint.upper) : json(nullptr)},
              {"effort", joint.effort},
              {"velocity", joint.velocity},
              {"axis", vector_json(joint.axis)}};
    if (joint.is_mimic)
      j["mimic"] = {{"joint", joint.mimic_source},
                    {"multiplier", joint.multiplier},
                    {"offset", joint.offset}};
    joints.push_back(j);
  }
  out["joints"] = joints;
  json links = json::array();
  for (const Link& link : model.links) {
    json collisions = json::array();
    for (const LinkGeometry& g : link.collisions) collisions.push_back(shape_name(g.shape.type));
    links.push_back({{"name", link.name},
                     {"parent", link.parent_link < 0 ? json(nullptr)
                                                     : json(model.links[link.parent_link].name)},
                     {"mass", link.inertial.mass},
                     {"collision", collisions},
                     {"visuals", link.visuals.size()}});
  }
  out["links"] = links;
  json surface_list = json::array();
  for (const Surface& s : surfaces) {
    if (s.is_point()) {  // a sphere at a point of the link: no normal, no polygon
      surface_list.push_back({{"name", s.name},
                              {"link", s.link_name},
                              {"point", vector_json(s.center_L())},
                              {"radius", s.radius}});
      continue;
    }
    json vertices = json::array();
    for (const auto& v : s.vertices_L()) vertices.push_back(vector_json(v));
    surface_list.push_back({{"name", s.name},
                            {"link", s.link_name},
                            {"normal", vector_json(s.normal_L())},
                            {"area", s.area()},
                            {"vertices", vertices}});
  }
  out["surfaces"] = surface_list;
  // The ignored inertia tensors: one warning line, and each link with its fault.
  json warnings = model.load_warnings;
  const std::string inertias = ignored_inertias_warning(model.source_file, model.ignored_inertias);
  if (!inertias.empty()) warnings.push_back(inertias);
  out["warnings"] = warnings;
  json ignored = json::array();
  for (const IgnoredInertia& i : model.ignored_inertias)
    ignored.push_back({{"link", i.link}, {"fault", i.fault}});
  out["ignored_inertias"] = ignored;
  return out;
}

void print_text(const json& d, std::ostream& out) {
  out << "model " << d["name"].get<std::string>() << "  (" << d["file"].get<std::string>() << ")\n";
  out << "kind: " << d["kind"].get<std::string>() << "   actuated dofs: " << d["dof"]
      << "   mass: " << std::fixed << std::setprecision(4) << d["mass"].get<double>() << " kg"
      << "   links: " << d["links"].size() << "\n";
  out << "joints (movable):\n";
  for (const json& j : d["joints"]) {
    out << "  " << std::left << std::setw(28) << j["name"].get<std::string>() << std::setw(11)
        << j["type"].get<std::string>() << std::right << std::setprecision(3);
    if (j["lower"].is_null())
      out << "        unbounded";
    else
      out << std::setw(8) << j["lower"].get<double>() << " .. " << std::setw(6)
          << j["upper"].get<double>();
    out << "   effort " << std::setw(7) << std::setprecision(1) << j["effort"].get<double>();
    if (j.contains("mimic")) out << "   mimics " << j["mimic"]["joint"].get<std::string>();
    out << "\n";
  }
  const json& c = d["collision"];
  out << "collision: " << c["shapes"] << " shapes on " << c["links_with_geometry"] << " links ("
      << c["mesh_hulls"] << " mesh convex hulls), " << c["candidate_pairs"]
      << " link pairs checked, " << c["srdf_disabled_pairs"] << " disabled by the SRDF\n";
  out << "surfaces: " << d["surfaces"].size() << "\n";
  for (const json& s : d["surfaces"]) {
    out << "  " << std::left << std::setw(16) << s["name"].get<std::string>() << " on "
        << std::setw(20) << s["link"].get<std::string>() << std::right;
    if (s.contains("radius")) {
      const json& p = s["point"];
      out << std::setprecision(4) << "point [" << p[0].get<double>() << ", " << p[1].get<double>()
          << ", " << p[2].get<double>() << "], radius " << s["radius"].get<double>() << " m\n";
      continue;
    }
    out << s["vertices"].size() << " vertices, " << std::setprecision(4) << s["area"].get<double>()
        << " m^2" << (s.contains("class") ? ", " + s["class"].get<std::string>() : "") << "\n";
  }
  // Extracted surfaces (--surfaces auto) are new to the reader: their normal and vertices too.
  for (const json& s : d["surfaces"]) {
    if (!s.contains("class")) continue;
    auto point = [&](const json& v) {
      out << " [" << v[0].get<double>() << ", " << v[1].get<double>() << ", " << v[2].get<double>()
          << "]";
    };
    out << "  " << s["name"].get<std::string>() << ": normal" << std::setprecision(4);
    point(s["normal"]);
    out << ", vertices (link frame, m)";
    for (const json& v : s["vertices"]) point(v);
    out << "\n";
  }
  for (const json& w : d["warnings"]) out << "warning: " << w.get<std::string>() << "\n";
}

}  // namespace

// Builds the model's collision objects (convex hulls of meshes, primitives) and counts the pairs
// the planner would check, with the SRDF's disabled pairs left out.
json collision_summary(const std::shared_ptr<const Model>& model, EntityKind kind,
                       const std::string& srdf) {
  System system;
  Entity entity;
  entity.name = model->name;
  entity.kind = kind;
  entity.model = model;
  system.add(entity);
  CollisionOptions options;
  if (!srdf.empty()) options.srdf_files.emplace_back(model->name, srdf);
  const CollisionModel collision(system, options);
  size_t hulls = 0;
  for (const CollisionShape& shape : collision.shapes()) hulls += shape.hull != nullptr;
  return {{"links_with_geometry", collision.links().size()},
          {"shapes", collision.shapes().size()},
          {"mesh_hulls", hulls},
          {"candidate_pairs", collision.pairs().size()},
          {"srdf_disabled_pairs", collision.num_srdf_disabled_pairs()}};
}

namespace {

// --collision-matrix: one line per disabled pair ("  link1 / link2: reason"), or one JSON object;
// --srdf-out writes them as an SRDF, atomically.
int inspect_collision_matrix(const InspectOptions& options,
                             const std::shared_ptr<const Model>& model, std::ostream& out) {
  CollisionMatrixOptions matrix_options;
  matrix_options.samples = options.samples;
  matrix_options.seed = options.seed;
  matrix_options.include_never = options.never;
  const CollisionMatrix matrix = compute_collision_matrix(model, matrix_options);
  auto name = [&](int link) { return model->links[link].name; };
  if (options.json) {
    json pairs = json::array();
    for (const MatrixPair& p : matrix.pairs)
      pairs.push_back({{"link1", name(p.link_a)},
                       {"link2", name(p.link_b)},
                       {"reason", to_string(p.reason)},
                       {"collisions", p.collisions}});
    out << json{{"robot", matrix.robot},
                {"samples", matrix.samples},
                {"seed", matrix.seed},
                {"pairs", pairs}}
               .dump(2)
        << "\n";
  } else {
    out << "self-collision matrix of " << matrix.robot << ": " << matrix.pairs.size()
        << (matrix.pairs.size() == 1 ? " pair" : " pairs") << " disabled ("
        << describe_counts(matrix) << ")\n";
    for (const MatrixPair& p : matrix.pairs) {
      out << "  " << name(p.link_a) << " / " << name(p.link_b) << ": " << to_string(p.reason);
      if (p.reason != DisabledReason::Adjacent)
        out << " (" << p.collisions << " of " << matrix.samples << " samples)";
      out << "\n";
    }
  }
  if (!options.srdf_out.empty()) {
    write_file_atomically(options.srdf_out, collision_matrix_srdf(*model, matrix));
    if (!options.json) out << "wrote " << options.srdf_out << "\n";
  }
  return 0;
}

}  // namespace

int run_inspect(const InspectOptions& options, std::ostream& out, std::ostream& err) {
  UrdfOptions urdf_options;
  urdf_options.packages.directories = options.package_paths;
  const auto model = std::make_shared<const Model>(load_urdf(options.urdf, urdf_options));
  if (options.collision_matrix) {
    for (const std::string& w : model->load_warnings) err << "warning: " << w << "\n";
    return inspect_collision_matrix(options, model, out);
  }
  // --surfaces auto: the surfaces `surfaces: auto` would give it in a scenario, root at the origin.
  std::vector<Surface> surfaces;
  std::vector<Affordance> extracted;
  if (options.surfaces == "auto")
    for (Affordance& a : extracted = extract_affordances(*model, Eigen::Isometry3d::Identity()))
      surfaces.push_back(a.surface);
  else if (!options.surfaces.empty())
    surfaces = load_surface_file(options.surfaces, *model);
  const EntityKind kind = decide_kind(options, *model);
  json description = describe(*model, kind, surfaces);
  for (size_t i = 0; i < extracted.size(); ++i)
    description["surfaces"][i]["class"] = to_string(extracted[i].kind);
  description["collision"] = collision_summary(model, kind, options.srdf);
  if (options.json)
    out << description.dump(2) << "\n";
  else
    print_text(description, out);
  if (options.json)
    for (const json& w : description["warnings"])
      err << "warning: " << w.get<std::string>() << "\n";
  if (!options.png.empty()) {
    const std::string caption = model->name + ": " + std::to_string(surfaces.size()) +
                                (surfaces.size() == 1 ? " surface" : " surfaces") +
                                (options.surfaces == "auto" ? " (extracted)" : "");
    write_surface_figure({model, kind, surfaces, options.png, options.view, caption});
    if (!options.json) out << "wrote " << options.png << "\n";
  }
  return 0;
}

}  // namespace stanceplan::app
