#pragma once
// How far apart two configurations of a motion are, in the units of the spacing options
// (MotionOptions): the largest joint step, and the largest step of a point of the given contact
// surfaces. A surface point moves by an affine function of the point for a rigid link, so its
// largest step over the polygon is at a vertex: vertices are enough. A reusable workspace: after
// construction, measure() allocates nothing.
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "planner/contact/surface_set.h"
#include "planner/model/model_data.h"
#include "planner/scene/scene.h"

namespace stanceplan {

struct SpacingMeasure {
  double joint = 0.0;  // largest joint step (rad, or m for a prismatic joint)
  int joint_entity = -1, joint_dof = -1;
  double point = 0.0;  // largest step of a surface vertex (m)
  SurfaceRef point_surface;
  // The larger of joint / joint_spacing and point / point_spacing: <= 1 when within both.
  double ratio(double joint_spacing, double point_spacing) const {
    return std::max(joint / joint_spacing, point / point_spacing);
  }
};

class SampleSpacing {
 public:
  // `surfaces`: the contact surfaces whose points are measured (those of moving links only count).
  SampleSpacing(const Scene& scene, const std::vector<SurfaceRef>& surfaces);

  SpacingMeasure measure(const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b);

  // For measuring one configuration against many (a tree's nearest node): the world positions of
  // the measured vertices at q, stored once per configuration (resized to num_vertices()), and
  // the measure between two configurations from them (no kinematics, no allocation).
  int num_vertices() const { return num_vertices_; }
  SurfaceRef vertex_surface(int i) const { return vertex_surfaces_[size_t(i)]; }
  void vertices(const Eigen::VectorXd& q, std::vector<Eigen::Vector3d>* p_W);
  SpacingMeasure measure(const Eigen::VectorXd& q_a, const std::vector<Eigen::Vector3d>& p_a_W,
                         const Eigen::VectorXd& q_b,
                         const std::vector<Eigen::Vector3d>& p_b_W) const;

  // "robot/l_knee_p" or "robot/l_sole" for the worst of a measure.
  std::string joint_name(const SpacingMeasure& m) const;
  std::string surface_name(const SpacingMeasure& m) const;

 private:
  struct MeasuredSurface {
    SurfaceRef ref;
    int link = -1;
    std::vector<Eigen::Vector3d> vertices_L;
  };
  void kinematics(const Eigen::VectorXd& q, std::vector<ModelData>& data) const;
  SpacingMeasure joint_measure(const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b) const;

  const Scene& scene_;
  std::vector<MeasuredSurface> surfaces_;
  int num_vertices_ = 0;
  std::vector<SurfaceRef> vertex_surfaces_;  // per vertex of vertices()
  std::vector<ModelData> data_a_, data_b_;
};

}  // namespace stanceplan
