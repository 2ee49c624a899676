#include "planner/search/reach_bound.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {
namespace {

// The largest distance a joint can put its child link's origin from its parent link's origin.
double joint_length(const Model& model, const Joint& joint) {
  const double offset = joint.T_PJ.translation().norm();
  if (joint.type != JointType::Prismatic) return offset;  // fixed, revolute, continuous
  const Joint& source = model.joints[model.dof_joints[joint.dof]];
  if (!source.has_position_limits) return INFINITY;
  // The joint's value is multiplier * q + offset with q in [lower, upper] (mimic joints too).
  const double travel = std::max(std::abs(joint.multiplier * source.lower + joint.offset),
                                 std::abs(joint.multiplier * source.upper + joint.offset));
  return offset + travel;
}

// The farthest point of a surface from its link's origin: a vertex of its polygon, or a point
// surface's centre plus its radius.
double surface_extent(const Surface& s) {
  double r = 0.0;
  for (const Eigen::Vector3d& v : s.vertices_L()) r = std::max(r, v.norm());
  return r + (s.is_point() ? s.radius : 0.0);
}

}  // namespace

double link_origin_reach(const Model& model, int link_a, int link_b) {
  double sum = 0.0;
  // Links are in topological order: the larger index is never an ancestor of the smaller, so
  // climbing from the larger one meets the common ancestor.
  while (link_a != link_b) {
    int& deeper = link_a > link_b ? link_a : link_b;
    sum += joint_length(model, model.joints[model.links[deeper].parent_joint]);
    deeper = model.links[deeper].parent_link;
  }
  return sum;
}

double ReachTable::between(SurfaceRef a, SurfaceRef b) {
  return reach_.get(a, b, [this](SurfaceRef lo, SurfaceRef hi) {
    const Surface& sa = scene_.surfaces.get(lo);
    const Surface& sb = scene_.surfaces.get(hi);
    const Model& model = *scene_.system.entity(lo.entity).model;
    return surface_extent(sa) + link_origin_reach(model, sa.link, sb.link) + surface_extent(sb);
  });
}

}  // namespace stanceplan
