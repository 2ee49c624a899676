#include "planner/contact/surface_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "planner/util/input_error.h"
#include "planner/util/text_file.h"

namespace stanceplan {
namespace {

const char* kFormat = "stanceplan/surfaces@1";

class SurfaceFileReader {
 public:
  SurfaceFileReader(const std::string& path, const Model& model) : path_(path), model_(model) {}

  std::vector<Surface> read() {
    YAML::Node root;
    try {
      root = YAML::Load(read_text_file(path_));
    } catch (const YAML::Exception& e) {
      throw InputError(path_ + ":" + std::to_string(e.mark.line + 1) +
                       ": not valid YAML: " + e.msg);
    }
    if (!root.IsMap()) fail(root, "", "expected a mapping with \"format\" and \"surfaces\"");
    const YAML::Node format = root["format"];
    if (!format || !format.IsScalar() || format.as<std::string>() != kFormat)
      fail(format ? format : root, "format",
           std::string("expected \"") + kFormat + "\"" +
               (format && format.IsScalar() ? ", found \"" + format.as<std::string>() + "\"" : ""));
    const YAML::Node list = root["surfaces"];
    if (!list || !list.IsSequence()) fail(root, "surfaces", "expected a list of surfaces");
    std::vector<Surface> surfaces;
    std::set<std::string> names;
    for (size_t i = 0; i < list.size(); ++i) {
      Surface s = read_surface(list[i], "surfaces[" + std::to_string(i) + "]");
      if (!names.insert(s.name).second)
        fail(list[i], "surface \"" + s.name + "\"", "the name is used twice");
      surfaces.push_back(std::move(s));
    }
    return surfaces;
  }

 private:
  [[noreturn]] void fail(const YAML::Node& node, const std::string& where,
                         const std::string& what) const {
    std::string message = path_;
    if (node.IsDefined() && node.Mark().line >= 0)
      message += ":" + std::to_string(node.Mark().line + 1);
    message += ": " + (where.empty() ? "" : where + ": ") + what;
    throw InputError(message);
  }

  Eigen::Vector3d read_vector(const YAML::Node& parent, const std::string& key,
                              const std::string& where) const {
    const YAML::Node node = parent[key];
    if (!node.IsSequence() || node.size() != 3)
      fail(node ? node : parent, where, key + ": expected [x, y, z]");
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = read_number(node[k], where + ": " + key);
    return v;
  }

  double read_number(const YAML::Node& node, const std::string& where) const {
    double value = 0.0;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      fail(node, where,
           "expected a number" + (node.IsScalar() ? ", found \"" + node.Scalar() + "\"" : ""));
    }
    if (!std::isfinite(value))
      fail(node, where, "expected a finite number, found \"" + node.Scalar() + "\"");
    return value;
  }

  Surface read_surface(const YAML::Node& node, const std::string& index_label) {
    if (!node.IsMap()) fail(node, index_label, "expected a mapping");
    if (!node["name"] || !node["name"].IsScalar()) fail(node, index_label, "name: missing");
    const std::string name = node["name"].as<std::string>();
    const std::string where = "surface \"" + name + "\"";
    if (!node["link"] || !node["link"].IsScalar()) fail(node, where, "link: missing");
    const std::string link_name = node["link"].as<std::string>();
    const int link = model_.find_link(link_name);
    if (link < 0)
      fail(node["link"], where,
           "link \"" + link_name + "\" is not in model \"" + model_.name + "\"");
    if (node["box_face"]) return read_box_face(node, where, name, link);
    if (!node["vertices"] || !node["vertices"].IsSequence())
      fail(node, where, "vertices: missing (or give box_face)");
    std::vector<Eigen::Vector3d> vertices;
    for (size_t i = 0; i < node["vertices"].size(); ++i) {
      const YAML::Node v = node["vertices"][i];
      if (!v.IsSequence() || v.size() != 3)
        fail(v, where, "vertices[" + std::to_string(i) + "]: expected [x, y, z]");
      vertices.emplace_back(read_number(v[0], where), read_number(v[1], where),
                            read_number(v[2], where));
    }
    if (!node["normal"])
      fail(node, where, "normal: missing (the outward normal in the link frame)");
    const Eigen::Vector3d normal = read_vector(node, "normal", where);
    Eigen::Vector3d x_axis;
    const bool has_x = static_cast<bool>(node["x_axis"]);
    if (has_x) x_axis = read_vector(node, "x_axis", where);
    Surface surface;
    std::string error;
    if (!make_surface(name, link, link_name, vertices, normal, has_x ? &x_axis : nullptr, &surface,
                      &error))
      fail(node["vertices"], where, error);
    return surface;
  }

  Surface read_box_face(const YAML::Node& node, const std::string& where, const std::string& name,
                        int link) {
    if (!node["box_face"].IsScalar())
      fail(node["box_face"], where, "box_face: expected one of +x -x +y -y +z -z");
    const std::string face = node["box_face"].Scalar();
    int box_index = 0;
    if (node["box_index"]) {
      const double index = read_number(node["box_index"], where + ": box_index");
      if (index != std::floor(index) || index < 0 || index > 1e6)
        fail(node["box_index"], where,
             "box_index: expected a whole number >= 0, found " + node["box_index"].Scalar());
      box_index = static_cast<int>(index);
    }
    const double inset = node["inset"] ? read_number(node["inset"], where + ": inset") : 0.0;
    try {
      return surface_from_box_face(model_, link, box_index, face, inset, name);
    } catch (const InputError& e) {
      fail(node["box_face"], where, e.what());
    }
  }

  std::string path_;
  const Model& model_;
};

}  // namespace

std::vector<Surface> load_surface_file(const std::string& path, const Model& model) {
  return SurfaceFileReader(path, model).read();
}

Surface surface_from_box_face(const Model& model, int link, int box_index, const std::string& face,
                              double inset, const std::string& name) {
  static const std::string kFaces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  int face_index = -1;
  for (int f = 0; f < 6; ++f)
    if (face == kFaces[f]) face_index = f;
  if (face_index < 0)
    throw InputError("box_face: expected one of +x -x +y -y +z -z, found \"" + face + "\"");
  const Link& l = model.links.at(link);
  const LinkGeometry* box = nullptr;
  int seen = 0;
  for (const LinkGeometry& g : l.collisions)
    if (g.shape.type == ShapeType::Box && seen++ == box_index) box = &g;
  if (!box)
    throw InputError("link \"" + l.name + "\" has " + std::to_string(seen) +
                     " collision box(es), box_index " + std::to_string(box_index) +
                     " does not exist");
  const int axis = face_index / 2;
  const double sign = face_index % 2 == 0 ? 1.0 : -1.0;
  // (u, v, sign * axis) right-handed, so corners listed (+,+) (-,+) (-,-) (+,-) are
  // counter-clockwise.
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  if (sign < 0) std::swap(u, v);
  const Eigen::Vector3d half = 0.5 * box->shape.size;
  const double hu = half[u] - inset, hv = half[v] - inset;
  if (hu <= 0.0 || hv <= 0.0)
    throw InputError("inset " + std::to_string(inset) + " m leaves nothing of face " + face +
                     " of link \"" + l.name + "\"");
  std::vector<Eigen::Vector3d> vertices;
  for (const auto& [su, sv] : {std::pair{1.0, 1.0}, {-1.0, 1.0}, {-1.0, -1.0}, {1.0, -1.0}}) {
    Eigen::Vector3d p_G = Eigen::Vector3d::Zero();
    p_G[axis] = sign * half[axis];
    p_G[u] = su * hu;
    p_G[v] = sv * hv;
    vertices.push_back(box->T_LG * p_G);
  }
  const Eigen::Vector3d normal = box->T_LG.linear() * (sign * Eigen::Vector3d::Unit(axis));
  const Eigen::Vector3d x_axis = box->T_LG.linear() * Eigen::Vector3d::Unit(u);
  Surface surface;
  std::string error;
  if (!make_surface(name, link, l.name, vertices, normal, &x_axis, &surface, &error, 1e-9))
    throw InputError("face " + face + " of link \"" + l.name + "\": " + error);
  return surface;
}

}  // namespace stanceplan
