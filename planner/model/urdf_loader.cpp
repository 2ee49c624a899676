#include "planner/model/urdf_loader.h"

#include <console_bridge/console.h>

#include <urdf_parser/urdf_parser.h>
#include <Eigen/Eigenvalues>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

#include "planner/util/input_error.h"
#include "planner/util/text_file.h"
#include "planner/util/xml_buffer.h"

namespace stanceplan {
namespace fs = std::filesystem;
namespace {

// urdfdom reports its faults through console_bridge, a process-wide logger. While parsing we
// install a handler that collects them so that the InputError can say what was wrong.
class CollectingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages.push_back(text);
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) ++errors;
  }
  std::vector<std::string> messages;
  int errors = 0;
};

// urdfdom 3.0 logs an error and still returns a model when an <inertial>, <visual> or
// <collision> does not parse (a NaN box size, mass="inf"): the element is dropped or half read.
// *errors counts those messages so that such a model is rejected rather than used.
urdf::ModelInterfaceSharedPtr parse_collecting(const std::string& xml,
                                               std::vector<std::string>* messages, int* errors) {
  static std::mutex console_mutex;  // console_bridge's handler is global state
  std::lock_guard<std::mutex> lock(console_mutex);
  CollectingHandler handler;
  console_bridge::useOutputHandler(&handler);
  const console_bridge::LogLevel previous_level = console_bridge::getLogLevel();
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_WARN);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml_parse_buffer(xml));  // NUL-padded: TinyXML reads past the end
  } catch (const std::exception& e) {
    handler.messages.push_back(e.what());
  }
  console_bridge::setLogLevel(previous_level);
  console_bridge::restorePreviousOutputHandler();
  *messages = handler.messages;
  *errors = handler.errors;
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

Eigen::Vector3d to_vector(const urdf::Vector3& v) {
  return Eigen::Vector3d(v.x, v.y, v.z);
}

// The shortest text that reads back as x ("0.1", "-1", "nan").
std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string numbers(const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i > 0) out += ' ';  // appended, not prepended: GCC 12 warns (-Wrestrict) on "" + string
    out += number(v[i]);
  }
  return out;
}

bool finite(const urdf::Pose& pose) {
  return std::isfinite(pose.position.x) && std::isfinite(pose.position.y) &&
         std::isfinite(pose.position.z) && std::isfinite(pose.rotation.x) &&
         std::isfinite(pose.rotation.y) && std::isfinite(pose.rotation.z) &&
         std::isfinite(pose.rotation.w);
}

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
    if (link.inertial) read_inertial(link.name, *link.inertial, &out.inertial);
    for (const auto& visual : link.visual_array)
      if (visual)
        add_geometry(link.name, "visual", visual->geometry, visual->origin, visual->material.get(),
                     &out.visuals);
    for (const auto& collision : link.collision_array)
      if (collision)
        add_geometry(link.name, "collision", collision->geometry, collision->origin, nullptr,
                     &out.collisions);
    if (parent_joint) out.parent_joint = add_joint(*parent_joint, parent_link, index);
    model_.links.push_back(std::move(out));
    for (const auto& child : link.child_links) add_link(*child, index, child->parent_joint.get());
  }

  // Faults that change the statics (a negative or non-finite mass, a centre of mass that cannot
  // be placed) are errors; faults of the tensor alone are recorded and the tensor set to zero
  // (planner/model/ignored_inertia.h).
  void read_inertial(const std::string& link_name, const urdf::Inertial& inertial, Inertial* out) {
    const std::string where = "link \"" + link_name + "\": <inertial> ";
    if (!finite(inertial.origin)) fail(where + "<origin>: expected finite numbers");
    if (!(inertial.mass >= 0.0))  // also NaN
      fail(where + "mass: expected a number >= 0 (kg), found " + number(inertial.mass));
    out->mass = inertial.mass;
    out->p_LC = to_vector(inertial.origin.position);
    Eigen::Matrix3d I;
    I << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
        inertial.ixz, inertial.iyz, inertial.izz;
    const std::string fault = inertia_fault(inertial.mass, I);
    if (!fault.empty()) {
      model_.ignored_inertias.push_back({link_name, fault});
      return;  // out->I_C stays zero
    }
    const Eigen::Matrix3d R = to_isometry(inertial.origin).linear();
    out->I_C = R * I * R.transpose();
  }

  // What no rigid body's rotational inertia can be ("" when the tensor is one): its principal
  // moments a, b, c are >= 0 with each at most the sum of the other two (they are sums of second
  // moments of the mass), and a massless link has none. A massless frame (mass 0, zero tensor:
  // the sensor and tool frames of TALOS and the Panda) is fine. Tolerances are relative to the
  // trace: a negative moment only at rounding level; the triangle inequality within 2 %, since
  // CAD exporters round the tensor (TALOS's gripper motor links exceed it by 1.3 %).
  static std::string inertia_fault(double mass, const Eigen::Matrix3d& I) {
    if (!I.allFinite())
      return "non-finite tensor " + numbers(Eigen::Map<const Eigen::VectorXd>(I.data(), 9));
    if (mass == 0.0 && !I.isZero(0.0)) return "a non-zero tensor on a link of mass 0";
    const Eigen::Vector3d moments =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly)
            .eigenvalues();  // ascending
    const double trace = std::abs(I.trace());
    if (moments[0] < -1e-9 * trace)
      return "not positive semi-definite: principal moments " + numbers(moments);
    if (moments[2] > moments[0] + moments[1] + 0.02 * trace)
      return "triangle inequality broken: principal moments " + numbers(moments) + ", " +
             number(moments[2]) + " > " + number(moments[0] + moments[1]);
    return "";
  }

  void add_geometry(const std::string& link_name, const std::string& kind,
                    const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin,
                    const urdf::Material* material, std::vector<LinkGeometry>* out) {
    if (!geometry) return;
    const std::string where = "link \"" + link_name + "\": " + kind + " ";
    if (!finite(origin)) fail(where + "<origin>: expected finite numbers");
    LinkGeometry g;
    g.T_LG = to_isometry(origin);
    // A material with a <texture> is drawn by ROS tools in that texture, and urdfdom reports its
    // missing <color> as opaque black: such a visual keeps the default colour instead.
    if (material && material->texture_filename.empty() &&
        (material->color.r || material->color.g || material->color.b || material->color.a)) {
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
    if (g.shape.type != ShapeType::Mesh) check_size(where, g.shape);
    out->push_back(std::move(g));
  }

  // Box sizes, radii and lengths must be positive; a negative one would turn a body inside out.
  void check_size(const std::string& where, const Shape& shape) const {
    const int count = shape.type == ShapeType::Box ? 3 : shape.type == ShapeType::Cylinder ? 2 : 1;
    const Eigen::VectorXd size = shape.size.head(count);
    if ((size.array() > 0.0).all()) return;  // false for NaN too
    const char* what = shape.type == ShapeType::Box        ? "<box> size"
                       : shape.type == ShapeType::Cylinder ? "<cylinder> radius and length"
                                                           : "<sphere> radius";
    fail(where + what + ": expected positive numbers (m), found " + numbers(size));
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
    const std::string where = "joint \"" + joint.name + "\": ";
    if (!finite(joint.parent_to_joint_origin_transform))
      fail(where + "<origin>: expected finite numbers");
    out.T_PJ = to_isometry(joint.parent_to_joint_origin_transform);
    switch (joint.type) {
      case urdf::Joint::REVOLUTE:
        out.type = JointType::Revolute;
        break;
      case urdf::Joint::CONTINUOUS:
        out.type = JointType::Continuous;
        break;
      case urdf::Joint::PRISMATIC:
        out.type = JointType::Prismatic;
        break;
      case urdf::Joint::FIXED:
        out.type = JointType::Fixed;
        break;
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
      if (!(axis.norm() >= 1e-9))  // also NaN
        fail(where + "<axis>: expected a non-zero finite vector, found " + numbers(axis));
      out.axis = axis.normalized();
      if (joint.limits) read_limits(where, *joint.limits, &out);
      if (joint.mimic) {
        if (!std::isfinite(joint.mimic->multiplier) || !std::isfinite(joint.mimic->offset))
          fail(where + "<mimic>: expected a finite multiplier and offset, found " +
               number(joint.mimic->multiplier) + " and " + number(joint.mimic->offset));
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

  void read_limits(const std::string& where, const urdf::JointLimits& limits, Joint* out) const {
    if (!(limits.effort >= 0.0))
      fail(where + "<limit> effort: expected a number >= 0, found " + number(limits.effort));
    if (!(limits.velocity >= 0.0))
      fail(where + "<limit> velocity: expected a number >= 0, found " + number(limits.velocity));
    out->effort = limits.effort;
    out->velocity = limits.velocity;
    if (out->type == JointType::Continuous) return;  // a continuous joint's lower/upper are unused
    if (!std::isfinite(limits.lower) || !std::isfinite(limits.upper) || limits.lower > limits.upper)
      fail(where + "<limit>: expected finite lower <= upper, found lower " + number(limits.lower) +
           " and upper " + number(limits.upper));
    out->has_position_limits = true;
    out->lower = limits.lower;
    out->upper = limits.upper;
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
      if (!std::isfinite(multiplier) || !std::isfinite(offset))
        fail("joint \"" + joint.name +
             "\": <mimic>: expected a chain whose composed multiplier "
             "and offset are finite, found " +
             number(multiplier) + " and " + number(offset));
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
  int errors = 0;
  const urdf::ModelInterfaceSharedPtr urdf = parse_collecting(xml, &messages, &errors);
  if (!urdf || errors > 0) {
    std::string what = display_name + ": not a valid URDF";
    if (!messages.empty()) what += ": " + join(messages, "; ");
    throw InputError(what);
  }
  Model model = Builder(display_name, base_dir, options).build(*urdf);
  for (const std::string& m : messages) model.load_warnings.push_back(display_name + ": " + m);
  return model;
}

Model load_urdf(const std::string& path, const UrdfOptions& options) {
  const std::string text = read_text_file(path);
  const std::string base_dir = fs::absolute(fs::path(path)).parent_path().string();
  Model model = load_urdf_string(text, base_dir, options, path);
  model.source_file = path;
  return model;
}

}  // namespace stanceplan
