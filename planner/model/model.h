#pragma once
// The const kinematic tree of one URDF (Pinocchio's model/data split: this is the model; the
// mutable workspace is ModelData). Links are stored in topological order: a link's parent always
// has a smaller index, links[0] is the root.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "planner/model/ignored_inertia.h"
#include "planner/model/shape.h"

namespace stanceplan {

enum class JointType { Fixed, Revolute, Continuous, Prismatic };

struct Inertial {
  double mass = 0.0;
  Eigen::Vector3d p_LC = Eigen::Vector3d::Zero();  // centre of mass in the link frame
  Eigen::Matrix3d I_C = Eigen::Matrix3d::Zero();   // inertia about the CoM, link axes
};

struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d T_PJ = Eigen::Isometry3d::Identity();  // joint frame in the parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();         // unit axis in the joint (= child) frame
  bool has_position_limits = false;
  double lower = 0.0;
  double upper = 0.0;
  double effort = 0.0;  // 0 means "no effort limit given"
  double velocity = 0.0;
  // Value of this joint = multiplier * q[dof] + offset. For an independent joint multiplier = 1,
  // offset = 0; for a mimic joint dof is its source's index. -1 for fixed joints.
  int dof = -1;
  double multiplier = 1.0;
  double offset = 0.0;
  bool is_mimic = false;
  std::string mimic_source;  // name of the mimicked joint (mimic only)

  bool movable() const { return type != JointType::Fixed; }
};

struct Link {
  std::string name;
  int parent_link = -1;   // -1 for the root
  int parent_joint = -1;  // index into Model::joints, -1 for the root
  Inertial inertial;
  std::vector<LinkGeometry> visuals;
  std::vector<LinkGeometry> collisions;
};

class Model {
 public:
  std::string name;
  std::string source_file;      // the URDF it was loaded from (empty if built in code)
  std::vector<Link> links;      // topological order, links[0] is the root
  std::vector<Joint> joints;    // every joint, in the order of their child links
  std::vector<int> dof_joints;  // dof_joints[k] = joint index driven directly by q[k]
  double total_mass = 0.0;
  std::vector<double> subtree_mass;        // per link: mass of the link and everything below it
  std::vector<std::string> load_warnings;  // non-fatal faults found while loading (skipped parts)
  // Links whose inertia tensor the loader set to zero (planner/model/ignored_inertia.h); the
  // one-line summary is ignored_inertias_warning(source_file, ignored_inertias).
  std::vector<IgnoredInertia> ignored_inertias;

  int num_dofs() const { return static_cast<int>(dof_joints.size()); }
  int num_links() const { return static_cast<int>(links.size()); }
  // -1 when absent.
  int find_link(const std::string& link_name) const;
  int find_joint(const std::string& joint_name) const;
  // Index k of the independent joint named joint_name in q, or -1.
  int find_dof(const std::string& joint_name) const;
  // True when a is an ancestor of b or b of a through exactly one joint.
  bool adjacent(int link_a, int link_b) const;

  // Recomputes total_mass and checks internal invariants (topological order, dof indices);
  // throws std::logic_error on a broken model. Called by every builder.
  void finalize();
};

}  // namespace stanceplan
