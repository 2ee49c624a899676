#include "planner/motion/sample_spacing.h"

#include <algorithm>
#include <cmath>

#include "planner/model/kinematics.h"

namespace stanceplan {

SampleSpacing::SampleSpacing(const Scene& scene, const std::vector<SurfaceRef>& surfaces)
    : scene_(scene) {
  const System& system = scene.system;
  for (SurfaceRef ref : surfaces) {
    if (system.entity(ref.entity).kind == EntityKind::Environment) continue;  // never moves
    const bool seen = std::any_of(surfaces_.begin(), surfaces_.end(),
                                  [&](const MeasuredSurface& m) { return m.ref == ref; });
    if (seen) continue;
    const Surface& s = scene.surfaces.get(ref);
    surfaces_.push_back({ref, s.link, s.vertices_L()});
    num_vertices_ += int(surfaces_.back().vertices_L.size());
    vertex_surfaces_.insert(vertex_surfaces_.end(), surfaces_.back().vertices_L.size(), ref);
  }
  for (int e = 0; e < system.num_entities(); ++e) {
    data_a_.emplace_back(system.entity(e));
    data_b_.emplace_back(system.entity(e));
  }
}

void SampleSpacing::kinematics(const Eigen::VectorXd& q, std::vector<ModelData>& data) const {
  const System& system = scene_.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    forward_kinematics(entity, q.segment(system.offset(e), entity.nq()), data[e]);
  }
}

SpacingMeasure SampleSpacing::joint_measure(const Eigen::VectorXd& q_a,
                                            const Eigen::VectorXd& q_b) const {
  SpacingMeasure m;
  const System& system = scene_.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    const int first = system.offset(e) + entity.first_dof();
    for (int k = 0; k < entity.model->num_dofs(); ++k) {
      const double step = std::abs(q_b[first + k] - q_a[first + k]);
      if (step > m.joint) m = {step, e, k, m.point, m.point_surface};
    }
  }
  return m;
}

void SampleSpacing::vertices(const Eigen::VectorXd& q, std::vector<Eigen::Vector3d>* p_W) {
  p_W->resize(size_t(num_vertices_));
  if (surfaces_.empty()) return;
  kinematics(q, data_a_);
  size_t i = 0;
  for (const MeasuredSurface& s : surfaces_) {
    const Eigen::Isometry3d& T_WL = data_a_[s.ref.entity].T_WL[s.link];
    for (const Eigen::Vector3d& p_L : s.vertices_L) (*p_W)[i++] = T_WL * p_L;
  }
}

SpacingMeasure SampleSpacing::measure(const Eigen::VectorXd& q_a,
                                      const std::vector<Eigen::Vector3d>& p_a_W,
                                      const Eigen::VectorXd& q_b,
                                      const std::vector<Eigen::Vector3d>& p_b_W) const {
  SpacingMeasure m = joint_measure(q_a, q_b);
  size_t i = 0;
  for (const MeasuredSurface& s : surfaces_)
    for (size_t v = 0; v < s.vertices_L.size(); ++v, ++i) {
      const double step = (p_b_W[i] - p_a_W[i]).norm();
      if (step > m.point) {
        m.point = step;
        m.point_surface = s.ref;
      }
    }
  return m;
}

SpacingMeasure SampleSpacing::measure(const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b) {
  SpacingMeasure m = joint_measure(q_a, q_b);
  if (surfaces_.empty()) return m;
  kinematics(q_a, data_a_);
  kinematics(q_b, data_b_);
  for (const MeasuredSurface& s : surfaces_) {
    const Eigen::Isometry3d& T_a = data_a_[s.ref.entity].T_WL[s.link];
    const Eigen::Isometry3d& T_b = data_b_[s.ref.entity].T_WL[s.link];
    for (const Eigen::Vector3d& p_L : s.vertices_L) {
      const double step = (T_b * p_L - T_a * p_L).norm();
      if (step > m.point) {
        m.point = step;
        m.point_surface = s.ref;
      }
    }
  }
  return m;
}

std::string SampleSpacing::joint_name(const SpacingMeasure& m) const {
  if (m.joint_entity < 0) return "";
  const Entity& entity = scene_.system.entity(m.joint_entity);
  return entity.name + "/" + entity.model->joints[entity.model->dof_joints[m.joint_dof]].name;
}

std::string SampleSpacing::surface_name(const SpacingMeasure& m) const {
  if (m.point_surface.entity < 0) return "";
  return scene_.surfaces.id(scene_.system, m.point_surface);
}

}  // namespace stanceplan
