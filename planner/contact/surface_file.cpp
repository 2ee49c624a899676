#include "planner/contact/surface_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include "planner/contact/link_faces.h"
#include "planner/util/input_error.h"
#include "planner/util/text_file.h"

namespace stanceplan {
namespace {

const char* kFormat = "stanceplan/surfaces@1";

// "+x" -> 0, "-x" -> 1, ..., "-z" -> 5 (axis = index / 2, minus when odd); -1 for anything else.
int axis_index(const std::string& name) {
  static const std::string kAxes[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  for (int i = 0; i < 6; ++i)
    if (name == kAxes[i]) return i;
  return -1;
}

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
    expect_keys(root, "", {"format", "surfaces"}, "");
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

  // Every key of `node` must be one of `keys`; a key that belongs to another kind of surface is
  // named as such. Same message as scenario files (planner/io/scenario.cpp).
  void expect_keys(const YAML::Node& node, const std::string& field,
                   const std::vector<std::string>& keys, const std::string& kind) const {
    static const std::set<std::string> kAnyKind = {"name",   "link",     "normal",    "vertices",
                                                   "x_axis", "box_face", "box_index", "inset",
                                                   "face",   "point",    "radius"};
    for (const auto& item : node) {
      const std::string key = item.first.IsScalar() ? item.first.Scalar() : "?";
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
      std::string known;
      for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
      const std::string what = kAnyKind.count(key) && !kind.empty()
                                   ? "not a field of a " + kind + " surface"
                                   : "unknown field";
      fail(item.first, field.empty() ? key : field + "." + key,
           what + " (expected one of: " + known + ")");
    }
  }

  // Which of vertices, box_face, face and point the surface is given by ("" when none).
  std::string kind_of(const YAML::Node& node, const std::string& index_label) const {
    std::string kind;
    for (const char* k : {"vertices", "box_face", "face", "point"}) {
      if (!node[k]) continue;
      if (!kind.empty())
        fail(node, index_label,
             "give one of vertices, box_face, face or point, found " + kind + " and " + k);
      kind = k;
    }
    return kind;
  }

  Surface read_surface(const YAML::Node& node, const std::string& index_label) {
    if (!node.IsMap()) fail(node, index_label, "expected a mapping");
    const std::string kind = kind_of(node, index_label);
    if (kind == "box_face")
      expect_keys(node, index_label, {"name", "link", "box_face", "box_index", "inset", "x_axis"},
                  kind);
    else if (kind == "face")
      expect_keys(node, index_label, {"name", "link", "face", "inset", "x_axis"}, kind);
    else if (kind == "point")
      expect_keys(node, index_label, {"name", "link", "point", "radius"}, kind);
    else
      expect_keys(node, index_label, {"name", "link", "normal", "vertices", "x_axis"},
                  kind.empty() ? "" : "vertices");
    if (!node["name"] || !node["name"].IsScalar()) fail(node, index_label, "name: missing");
    const std::string name = node["name"].as<std::string>();
    const std::string where = "surface \"" + name + "\"";
    if (!node["link"] || !node["link"].IsScalar()) fail(node, where, "link: missing");
    const std::string link_name = node["link"].as<std::string>();
    const int link = model_.find_link(link_name);
    if (link < 0)
      fail(node["link"], where,
           "link \"" + link_name + "\" is not in model \"" + model_.name + "\"");
    if (kind == "box_face") return read_box_face(node, where, name, link);
    if (kind == "face") return read_link_face(node, where, name, link);
    if (kind == "point") return read_point(node, where, name, link, link_name);
    return read_polygon(node, where, name, link, link_name);
  }

  Surface read_polygon(const YAML::Node& node, const std::string& where, const std::string& name,
                       int link, const std::string& link_name) {
    if (!node["vertices"] || !node["vertices"].IsSequence())
      fail(node, where, "vertices: missing (or give box_face, face or point)");
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
    const std::optional<Eigen::Vector3d> x_axis = read_x_axis(node, where);
    Surface surface;
    std::string error;
    if (!make_surface(name, link, link_name, vertices, normal, x_axis ? &*x_axis : nullptr,
                      &surface, &error))
      fail(node["vertices"], where, error);
    return surface;
  }

  // A sphere of `radius` at `point` (link frame): a round fingertip (surface.h, point surfaces).
  Surface read_point(const YAML::Node& node, const std::string& where, const std::string& name,
                     int link, const std::string& link_name) {
    const Eigen::Vector3d p_L = read_vector(node, "point", where);
    if (!node["radius"])
      fail(node, where, "radius: missing (the radius of the sphere at the point, m; 0 for a tip)");
    const double radius = read_number(node["radius"], where + ": radius");
    if (radius < 0.0)
      fail(node["radius"], where,
           "radius: expected a length >= 0 (m), found " + node["radius"].Scalar());
    Surface surface;
    std::string error;
    if (!make_point_surface(name, link, link_name, p_L, radius, &surface, &error))
      fail(node["point"], where, error);
    return surface;
  }

  std::optional<Eigen::Vector3d> read_x_axis(const YAML::Node& node, const std::string& where) {
    if (!node["x_axis"]) return std::nullopt;
    return read_vector(node, "x_axis", where);
  }

  double read_inset(const YAML::Node& node, const std::string& where) const {
    if (!node["inset"]) return 0.0;
    const double inset = read_number(node["inset"], where + ": inset");
    if (inset < 0.0)
      fail(node["inset"], where,
           "inset: expected a margin >= 0 (m), found " + node["inset"].Scalar());
    return inset;
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
    const double inset = read_inset(node, where);
    const std::optional<Eigen::Vector3d> x_axis = read_x_axis(node, where);
    try {
      return surface_from_box_face(model_, link, box_index, face, inset, name,
                                   x_axis ? &*x_axis : nullptr);
    } catch (const InputError& e) {
      fail(node["box_face"], where, e.what());
    }
  }

  // `face: -z` or `face: [0, 0, -1]`: the direction, link frame, and its name for messages.
  Eigen::Vector3d read_face_direction(const YAML::Node& node, const std::string& where,
                                      std::string* label) const {
    const YAML::Node face = node["face"];
    if (face.IsScalar()) {
      *label = face.Scalar();
      const int axis = axis_index(*label);
      if (axis < 0)
        fail(face, where,
             "face: expected one of +x -x +y -y +z -z or a direction [x, y, z], found \"" + *label +
                 "\"");
      return (axis % 2 == 0 ? 1.0 : -1.0) * Eigen::Vector3d::Unit(axis / 2);
    }
    const Eigen::Vector3d direction = read_vector(node, "face", where);
    if (direction.norm() < 1e-9) fail(face, where, "face: the direction [0, 0, 0] has no sense");
    std::ostringstream text;
    text << "[" << face[0].Scalar() << ", " << face[1].Scalar() << ", " << face[2].Scalar() << "]";
    *label = text.str();
    return direction;
  }

  Surface read_link_face(const YAML::Node& node, const std::string& where, const std::string& name,
                         int link) {
    std::string label;
    const Eigen::Vector3d direction = read_face_direction(node, where, &label);
    const double inset = read_inset(node, where);
    const std::optional<Eigen::Vector3d> x_axis = read_x_axis(node, where);
    try {
      return surface_from_link_face(model_, link, direction, label, inset,
                                    x_axis ? &*x_axis : nullptr, name);
    } catch (const InputError& e) {
      fail(node["face"], where, e.what());
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
                              double inset, const std::string& name,
                              const Eigen::Vector3d* x_axis_L) {
  const int face_index = axis_index(face);
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
  const PlanarFace whole = box_face(*box, face_index / 2, face_index % 2 == 0 ? 1.0 : -1.0);
  const PlanarFace shrunk = inset_face(whole, inset, 0.0);
  if (shrunk.vertices.empty())
    throw InputError("inset " + std::to_string(inset) + " m leaves nothing of face " + face +
                     " of link \"" + l.name + "\"");
  // Default x axis: the box's first axis in the face (from vertex 1 to vertex 0 of the whole face).
  const Eigen::Vector3d box_x = (whole.vertices[0] - whole.vertices[1]).normalized();
  Surface surface;
  std::string error;
  if (!make_surface(name, link, l.name, shrunk.vertices, whole.normal, x_axis_L ? x_axis_L : &box_x,
                    &surface, &error, 1e-9))
    throw InputError("face " + face + " of link \"" + l.name + "\": " + error);
  return surface;
}

}  // namespace stanceplan
