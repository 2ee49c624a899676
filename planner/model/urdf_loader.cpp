#include "planner/model/urdf_loader.h"

#include <console_bridge/console.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <urdf_parser/urdf_parser.h>

#include "planner/util/input_error.h"

namespace stanceplan {
namespace fs = std::filesystem;
namespace {

// urdfdom reports its faults through console_bridge, a process-wide logger. While parsing we
// install a handler that collects them so that the InputError can say what was wrong.
class CollectingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages.push_back(text);
  }
  std::vector<std::string> messages;
};

urdf::ModelInterfaceSharedPtr parse_collecting(const std::string& xml,
                                               std::vector<std::string>* messages) {
  static std::mutex console_mutex;  // console_bridge's handler is global state
  std::lock_guard<std::mutex> lock(console_mutex);
  CollectingHandler handler;
  console_bridge::useOutputHandler(&handler);
  const console_bridge::LogLevel previous_level = console_bridge::getLogLevel();
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_WARN);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    handler.messages.push_back(e.what());
  }
  console_bridge::setLogLevel(previous_level);
  console_bridge::restorePreviousOutputHandler();
  *messages = handler.messages;
  return model;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  Eigen::Quaterniond quat(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  T.linear() = quat.normalized().toRotationMatrix();
  return T;
}

Eigen::Vector3d to_vector(const urdf::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

class Builder {
 public:
  Builder(const std::string& display_name, const std::string& base_dir, const UrdfOptions& options)
      : file_(display_name), base_dir_(base_dir), options_(options) {}

  Model build(const urdf::ModelInterface& urdf) {
    model_.name = urdf.getName();
    const urdf::LinkConstSharedPtr root = urdf.getRoot();
    if (!root) fail("the model has no root link");
    add_link(*root, -1, nullptr);
    resolve_mimics();
    model_.finalize();
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + ": " + what); }

  void add_link(const urdf::Link& link, int parent_link, const urdf::Joint* parent_joint) {
    const int index = model_.num_links();
    Link out;
    out.name = link.name;
    out.parent_link = parent_link;
    if (link.inertial) read_inertial(*link.inertial, &out.inertial);
    for (const auto& visual : link.visual_array)
      if (visual) add_geometry(link.name, "visual", visual->geometry, visual->origin,
                               visual->material.get(), &out.visuals);
    for (const auto& collision : link.collision_array)
      if (collision) add_geometry(link.name, "collision", collision->geometry, collision->origin,
                                  nullptr, &out.collisions);
    if (parent_joint) out.parent_joint = add_joint(*parent_joint, parent_link, index);
    model_.links.push_back(std::move(out));
    for (const auto& child : link.child_links) add_link(*child, index, child->parent_joint.get());
  }

  void read_inertial(const urdf::Inertial& inertial, Inertial* out) {
    out->mass = inertial.mass;
    out->p_LC = to_vector(inertial.origin.position);
    Eigen::Matrix3d I;
    I << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
        inertial.ixz, inertial.iyz, inertial.izz;
    const Eigen::Matrix3d R = to_isometry(inertial.origin).linear();
    out->I_C = R * I * R.transpose();
  }

  void add_geometry(const std::string& link_name, const std::string& kind,
                    const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin,
                    const urdf::Material* material, std::vector<LinkGeometry>* out) {
    if (!geometry) return;
    LinkGeometry g;
    g.T_LG = to_isometry(origin);
    if (material && (material->color.r || material->color.g || material->color.b ||
                     material->color.a)) {
      g.has_color = true;
      g.rgba = Eigen::Vector4d(material->color.r, material->color.g, material->color.b,
                               material->color.a);
    }
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        g.shape.type = ShapeType::Box;
        g.shape.size = to_vector(box.dim);
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        g.shape.type = ShapeType::Cylinder;
        g.shape.size = Eigen::Vector3d(cylinder.radius, cylinder.length, 0.0);
        break;
      }
      case urdf::Geometry::SPHERE: {
        const auto& sphere = static_cast<const urdf::Sphere&>(*geometry);
        g.shape.type = ShapeType::Sphere;
        g.shape.size = Eigen::Vector3d(sphere.radius, 0.0, 0.0);
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(*geometry);
        g.shape.type = ShapeType::Mesh;
        g.shape.mesh_uri = mesh.filename;
        g.shape.mesh_scale = to_vector(mesh.scale);
        if (!resolve_mesh(link_name, kind, &g.shape)) return;
        break;
      }
    }
    out->push_back(std::move(g));
  }

  // False when a visual mesh is missing and tolerated (the geometry is skipped with a warning).
  bool resolve_mesh(const std::string& link_name, const std::string& kind, Shape* shape) {
    std::vector<std::string> tried;
    const auto path = resolve_uri(shape->mesh_uri, base_dir_, options_.packages, &tried);
    if (path) {
      shape->mesh_path = *path;
      return true;
    }
    std::string what = "link \"" + link_name + "\": " + kind + " mesh \"" + shape->mesh_uri +
                       "\" cannot be resolved";
    what += tried.empty() ? " (no package directory given: use --package-path or ROS_PACKAGE_PATH)"
                          : "; tried: " + join(tried, ", ");
    if (kind == "collision" || options_.require_visual_meshes) fail(what);
    model_.load_warnings.push_back(file_ + ": " + what + " (skipped)");
    return false;
  }

  int add_joint(const urdf::Joint& joint, int parent_link, int child_link) {
    Joint out;
    out.name = joint.name;
    out.parent_link = parent_link;
    out.child_link = child_link;
    out.T_PJ = to_isometry(joint.parent_to_joint_origin_transform);
    switch (joint.type) {
      case urdf::Joint::REVOLUTE: out.type = JointType::Revolute; break;
      case urdf::Joint::CONTINUOUS: out.type = JointType::Continuous; break;
      case urdf::Joint::PRISMATIC: out.type = JointType::Prismatic; break;
      case urdf::Joint::FIXED: out.type = JointType::Fixed; break;
      case urdf::Joint::FLOATING:
      case urdf::Joint::PLANAR:
      case urdf::Joint::UNKNOWN:
        fail("joint \"" + joint.name + "\": type " +
             (joint.type == urdf::Joint::FLOATING ? std::string("floating")
              : joint.type == urdf::Joint::PLANAR ? std::string("planar")
                                                  : std::string("unknown")) +
             " is not supported inside a model (a free root is given by the entity kind "
             "\"floating\" or \"object\" in the scenario)");
    }
    if (out.movable()) {
      const Eigen::Vector3d axis = to_vector(joint.axis);
      if (axis.norm() < 1e-9) fail("joint \"" + joint.name + "\": the axis is zero");
      out.axis = axis.normalized();
      if (joint.limits) {
        out.effort = joint.limits->effort;
        out.velocity = joint.limits->velocity;
        if (out.type != JointType::Continuous) {
          out.has_position_limits = true;
          out.lower = joint.limits->lower;
          out.upper = joint.limits->upper;
          if (out.lower > out.upper)
            fail("joint \"" + joint.name + "\": lower limit " + std::to_string(out.lower) +
                 " is above the upper limit " + std::to_string(out.upper));
        }
      }
      if (joint.mimic) {
        out.is_mimic = true;
        out.mimic_source = joint.mimic->joint_name;
        out.multiplier = joint.mimic->multiplier;
        out.offset = joint.mimic->offset;
      } else {
        out.dof = model_.num_dofs();
        model_.dof_joints.push_back(static_cast<int>(model_.joints.size()));
      }
    }
    model_.joints.push_back(std::move(out));
    return static_cast<int>(model_.joints.size()) - 1;
  }

  // A mimic joint's value is multiplier * source + offset; chains of mimics are composed.
  void resolve_mimics() {
    for (Joint& joint : model_.joints) {
      if (!joint.is_mimic) continue;
      double multiplier = joint.multiplier;
      double offset = joint.offset;
      std::string source = joint.mimic_source;
      for (size_t hops = 0;; ++hops) {
        const int s = model_.find_joint(source);
        if (s < 0)
          fail("joint \"" + joint.name + "\": mimics \"" + source + "\", which does not exist");
        const Joint& src = model_.joints[s];
        if (!src.movable())
          fail("joint \"" + joint.name + "\": mimics \"" + source + "\", which is fixed");
        if (hops > model_.joints.size())
          fail("joint \"" + joint.name + "\": its mimic chain is a loop");
        if (!src.is_mimic) {
          joint.dof = src.dof;
          break;
        }
        offset = multiplier * src.offset + offset;
        multiplier *= src.multiplier;
        source = src.mimic_source;
      }
      joint.multiplier = multiplier;
      joint.offset = offset;
    }
  }

  std::string file_;
  std::string base_dir_;
  const UrdfOptions& options_;
  Model model_;
};

}  // namespace

Model load_urdf_string(const std::string& xml, const std::string& base_dir,
                       const UrdfOptions& options, const std::string& display_name) {
  std::vector<std::string> messages;
  const urdf::ModelInterfaceSharedPtr urdf = parse_collecting(xml, &messages);
  if (!urdf) {
    std::string what = display_name + ": not a valid URDF";
    if (!messages.empty()) what += ": " + join(messages, "; ");
    throw InputError(what);
  }
  Model model = Builder(display_name, base_dir, options).build(*urdf);
  for (const std::string& m : messages) model.load_warnings.push_back(display_name + ": " + m);
  return model;
}

Model load_urdf(const std::string& path, const UrdfOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be opened for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string base_dir = fs::absolute(fs::path(path)).parent_path().string();
  Model model = load_urdf_string(buffer.str(), base_dir, options, path);
  model.source_file = path;
  return model;
}

}  // namespace stanceplan
