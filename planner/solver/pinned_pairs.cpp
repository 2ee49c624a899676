#include "planner/solver/pinned_pairs.h"

#include <algorithm>
#include <cmath>

#include "planner/collision/signed_distance.h"

namespace stanceplan {
namespace {

int collision_link_of(const Scene& scene, SurfaceRef ref) {
  return scene.collision->find_link(ref.entity, scene.surfaces.get(ref).link);
}

// s1's frame in s2's frame under a placement (E10-E13): origin (x, y, standoff), z1 = -z2, x1 at
// angle theta from x2 in s2's plane, y1 = z1 x x1.
Eigen::Isometry3d T_S2S1(const Placement& placement, double standoff) {
  const double c = std::cos(placement.theta), s = std::sin(placement.theta);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << c, s, 0.0, s, -c, 0.0, 0.0, 0.0, -1.0;
  T.translation() = Eigen::Vector3d(placement.x, placement.y, standoff);
  return T;
}

// Per collision link, the request contact pinning it; -1 for a link that never moves; -2 for a
// link free to move.
std::vector<int> pinning_contact(const Scene& scene, const PostureRequest& request) {
  const CollisionModel& model = *scene.collision;
  std::vector<int> by(model.links().size(), -2);
  for (size_t i = 0; i < model.links().size(); ++i)
    if (!model.links()[i].moves) by[i] = -1;
  for (size_t t = 0; t < request.contacts.size(); ++t) {
    const ContactTask& task = request.contacts[t];
    // A point contact pins nothing: the sphere may turn about its centre at any placement.
    if (!task.placement || scene.surfaces.get(task.contact.s1).is_point()) continue;
    const int a = collision_link_of(scene, task.contact.s1);
    const int b = collision_link_of(scene, task.contact.s2);
    if (a < 0 || b < 0) continue;
    if (!model.links()[b].moves && model.links()[a].moves) by[a] = int(t);
    if (!model.links()[a].moves && model.links()[b].moves) by[b] = int(t);
  }
  return by;
}

}  // namespace

std::vector<PairExclusion> pair_exclusions(const Scene& scene, const PostureRequest& request) {
  if (!scene.collision) return {};
  const CollisionModel& model = *scene.collision;
  std::vector<PairExclusion> why(model.pairs().size(), PairExclusion::None);
  const std::vector<int> pinned_by = pinning_contact(scene, request);
  for (size_t p = 0; p < model.pairs().size(); ++p)
    if (pinned_by[model.pairs()[p].a] >= -1 && pinned_by[model.pairs()[p].b] >= -1)
      why[p] = PairExclusion::Pinned;
  for (const ContactTask& task : request.contacts) {  // touching outranks pinned
    const Contact& c = task.contact;
    const int p = model.find_pair(c.s1.entity, scene.surfaces.get(c.s1).link, c.s2.entity,
                                  scene.surfaces.get(c.s2).link);
    if (p >= 0) why[p] = PairExclusion::Touching;
  }
  return why;
}

bool has_pinned_pair(const Scene& scene, const PostureRequest& request) {
  const std::vector<PairExclusion> why = pair_exclusions(scene, request);
  return std::find(why.begin(), why.end(), PairExclusion::Pinned) != why.end();
}

Eigen::Isometry3d pinned_link_pose(const Scene& scene, const ContactTask& task, SurfaceRef moving,
                                   const Eigen::Isometry3d& T_WL_other) {
  const Surface& s1 = scene.surfaces.get(task.contact.s1);
  const Surface& s2 = scene.surfaces.get(task.contact.s2);
  const Eigen::Isometry3d T = T_S2S1(*task.placement, task.standoff);
  if (moving == task.contact.s1) return T_WL_other * s2.T_LS * T * s1.T_LS.inverse();
  return T_WL_other * s1.T_LS * T.inverse() * s2.T_LS.inverse();
}

void place_pinned_links(const Scene& scene, const PostureRequest& request,
                        std::vector<ModelData>& data) {
  if (!scene.collision) return;
  const CollisionModel& model = *scene.collision;
  const std::vector<int> pinned_by = pinning_contact(scene, request);
  for (size_t i = 0; i < pinned_by.size(); ++i) {
    if (pinned_by[i] < 0) continue;
    const ContactTask& task = request.contacts[size_t(pinned_by[i])];
    const CollisionLink& link = model.links()[i];
    const bool is_s1 = task.contact.s1.entity == link.entity &&
                       scene.surfaces.get(task.contact.s1).link == link.link;
    const SurfaceRef moving = is_s1 ? task.contact.s1 : task.contact.s2;
    const SurfaceRef other = is_s1 ? task.contact.s2 : task.contact.s1;
    const Eigen::Isometry3d T_WL_other =
        data[size_t(other.entity)].T_WL[size_t(scene.surfaces.get(other).link)];
    data[size_t(link.entity)].T_WL[size_t(link.link)] =
        pinned_link_pose(scene, task, moving, T_WL_other);
  }
}

std::vector<PinnedPairDistance> pinned_pair_distances(const Scene& scene,
                                                      const PostureRequest& request,
                                                      std::span<const ModelData> data) {
  std::vector<PinnedPairDistance> out;
  if (!scene.collision) return out;
  const CollisionModel& model = *scene.collision;
  const std::vector<PairExclusion> why = pair_exclusions(scene, request);
  if (std::find(why.begin(), why.end(), PairExclusion::Pinned) == why.end()) return out;
  const std::vector<int> pinned_by = pinning_contact(scene, request);
  CollisionData work(scene.system, model);
  work.update(model, data);
  for (size_t p = 0; p < why.size(); ++p) {
    if (why[p] != PairExclusion::Pinned) continue;
    const CollisionPair& pair = model.pairs()[p];
    out.push_back({int(p), signed_distance(model, work, int(p)).distance,
                   std::max(-1, pinned_by[pair.a]), std::max(-1, pinned_by[pair.b])});
  }
  return out;
}

std::string collision_link_name(const Scene& scene, int l) {
  const CollisionLink& link = scene.collision->links()[size_t(l)];
  const Entity& e = scene.system.entity(link.entity);
  return e.name + "/" + e.model->links[size_t(link.link)].name;
}

}  // namespace stanceplan
