#include "planner/search/normal_angle_range.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stanceplan {
namespace {

// The joints from `link` up to (not including) `ancestor`, child first.
std::vector<int> joints_up_to(const Model& model, int link, int ancestor) {
  std::vector<int> joints;
  for (int l = link; l != ancestor; l = model.links[l].parent_link)
    joints.push_back(model.links[l].parent_joint);
  return joints;
}

int common_ancestor(const Model& model, int a, int b) {
  // Links are in topological order: the larger index is never an ancestor of the smaller.
  while (a != b) {
    if (a > b)
      a = model.links[a].parent_link;
    else
      b = model.links[b].parent_link;
  }
  return a;
}

bool rotates(const Joint& j) {
  return j.type == JointType::Revolute || j.type == JointType::Continuous;
}

struct DofBox {
  int dof;
  double lower, upper;
  double lipschitz;  // sum of |multiplier| of the path's joints driven by this dof
};

// The dofs that turn the path's joints, with the box of their values.
std::vector<DofBox> path_dofs(const Model& model, const std::vector<int>& joints) {
  std::vector<DofBox> boxes;
  for (int j : joints) {
    const Joint& joint = model.joints[j];
    if (!rotates(joint)) continue;
    auto it = std::find_if(boxes.begin(), boxes.end(),
                           [&](const DofBox& b) { return b.dof == joint.dof; });
    if (it == boxes.end()) {
      const Joint& source = model.joints[model.dof_joints[joint.dof]];
      const bool limited = source.type == JointType::Revolute && source.has_position_limits;
      boxes.push_back(
          {joint.dof, limited ? source.lower : -M_PI, limited ? source.upper : M_PI, 0.0});
      it = boxes.end() - 1;
    }
    it->lipschitz += std::abs(joint.multiplier);
  }
  return boxes;
}

// R_AL: the rotation of `link` in the frame of its ancestor at the end of `joints` (child first).
Eigen::Matrix3d rotation_along(const Model& model, const std::vector<int>& joints,
                               const Eigen::VectorXd& q) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  for (int j : joints) {
    const Joint& joint = model.joints[j];
    Eigen::Matrix3d R_PC = joint.T_PJ.linear();
    if (rotates(joint))
      R_PC = R_PC * Eigen::AngleAxisd(joint.multiplier * q[joint.dof] + joint.offset, joint.axis)
                        .toRotationMatrix();
    R = R_PC * R;
  }
  return R;
}

}  // namespace

AngleRange normal_angle_range(const Model& model, int link_a, const Eigen::Vector3d& u_a,
                              int link_b, const Eigen::Vector3d& u_b) {
  const int top = common_ancestor(model, link_a, link_b);
  const std::vector<int> up_a = joints_up_to(model, link_a, top);
  const std::vector<int> up_b = joints_up_to(model, link_b, top);
  std::vector<int> path = up_a;
  path.insert(path.end(), up_b.begin(), up_b.end());
  const std::vector<DofBox> dofs = path_dofs(model, path);
  if (static_cast<int>(dofs.size()) > kMaxGridDofs) return {};
  const int n = dofs.empty()
                    ? 1
                    : std::max(2, static_cast<int>(std::floor(std::pow(
                                      kGridPoints, 1.0 / static_cast<double>(dofs.size())))));
  double margin = 0.0;
  for (const DofBox& d : dofs) margin += d.lipschitz * 0.5 * (d.upper - d.lower) / (n - 1);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.num_dofs());
  AngleRange range{INFINITY, -INFINITY};
  std::vector<int> index(dofs.size(), 0);
  for (bool more = true; more;) {
    for (size_t k = 0; k < dofs.size(); ++k)
      q[dofs[k].dof] = dofs[k].lower + (dofs[k].upper - dofs[k].lower) * index[k] / (n - 1);
    const Eigen::Vector3d a = rotation_along(model, up_a, q) * u_a;
    const Eigen::Vector3d b = rotation_along(model, up_b, q) * u_b;
    const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
    range.lo = std::min(range.lo, angle);
    range.hi = std::max(range.hi, angle);
    more = false;  // next grid point (odometer order)
    for (size_t k = 0; k < dofs.size() && !more; ++k) {
      if (++index[k] < n)
        more = true;
      else
        index[k] = 0;
    }
  }
  return {std::max(0.0, range.lo - margin), std::min(M_PI, range.hi + margin)};
}

const AngleRange& NormalAngleTable::between(SurfaceRef a, SurfaceRef b) {
  return ranges_.get(a, b, [this](SurfaceRef lo, SurfaceRef hi) {
    const Surface& sa = scene_.surfaces.get(lo);
    const Surface& sb = scene_.surfaces.get(hi);
    const Model& model = *scene_.system.entity(lo.entity).model;
    return normal_angle_range(model, sa.link, sa.normal_L(), sb.link, sb.normal_L());
  });
}

}  // namespace stanceplan
