#include "planner/guide/guide_validity.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "planner/collision/signed_distance.h"
#include "planner/contact/polygon.h"
#include "planner/model/kinematics.h"
#include "planner/solver/pinned_pairs.h"

namespace stanceplan {

bool offered(const Scene& scene, SurfaceRef a, SurfaceRef b,
             const std::vector<std::pair<std::string, std::string>>& patterns) {
  if (patterns.empty()) return true;
  const std::string ia = scene.surfaces.id(scene.system, a),
                    ib = scene.surfaces.id(scene.system, b);
  for (const auto& [p1, p2] : patterns)
    if ((fnmatch(p1.c_str(), ia.c_str(), 0) == 0 && fnmatch(p2.c_str(), ib.c_str(), 0) == 0) ||
        (fnmatch(p1.c_str(), ib.c_str(), 0) == 0 && fnmatch(p2.c_str(), ia.c_str(), 0) == 0))
      return true;
  return false;
}

namespace {

// Whether link `link` of entity e carries a surface that the contact pairs let touch a surface
// on link `other_link` of entity f.
bool may_touch(const Scene& scene, int e, int link, int f, int other_link,
               const std::vector<std::pair<std::string, std::string>>& patterns) {
  for (int i = 0; i < int(scene.surfaces.of(e).size()); ++i) {
    if (scene.surfaces.of(e)[size_t(i)].link != link) continue;
    for (int j = 0; j < int(scene.surfaces.of(f).size()); ++j)
      if (scene.surfaces.of(f)[size_t(j)].link == other_link &&
          offered(scene, {e, i}, {f, j}, patterns))
        return true;
  }
  return false;
}

// Whether fixed robot r has a surface the contact pairs let touch object o: a carrier of it, whose
// moving links (its arm, its fingers) move with the object (hand_over.h), never obstacles in the
// object's way.
bool carries(const Scene& scene, int r, int o,
             const std::vector<std::pair<std::string, std::string>>& patterns) {
  for (int i = 0; i < int(scene.surfaces.of(r).size()); ++i)
    for (int j = 0; j < int(scene.surfaces.of(o).size()); ++j)
      if (offered(scene, {r, i}, {o, j}, patterns)) return true;
  return false;
}

enum class PairRule { Clearance, Touch, Ignored };

// The rule of each candidate pair (guide_validity.h): limbs that may touch are ignored, the links
// of a stance's contact may touch, the rest keep the clearance.
std::vector<PairRule> pair_rules(const Problem& problem, const GuideOptions& options) {
  const Scene& scene = problem.scene;
  const CollisionModel& model = *scene.collision;
  std::vector<PairRule> rules(model.pairs().size(), PairRule::Clearance);
  // The links of the stances' contacts (on floating robots: the task's supporting limbs).
  std::set<std::pair<int, int>> stance_links;
  for (const auto* stance : {&problem.initial_stance, &problem.goal_stance})
    for (const StanceContact& c : *stance) {
      const Surface& s1 = scene.surfaces.get(c.contact.s1);
      const Surface& s2 = scene.surfaces.get(c.contact.s2);
      const int pair = model.find_pair(c.contact.s1.entity, s1.link, c.contact.s2.entity, s2.link);
      if (pair >= 0) rules[size_t(pair)] = PairRule::Touch;
      stance_links.insert({{c.contact.s1.entity, s1.link}, {c.contact.s2.entity, s2.link}});
    }
  for (size_t p = 0; p < rules.size(); ++p) {
    const CollisionLink& a = model.links()[size_t(model.pairs()[p].a)];
    const CollisionLink& b = model.links()[size_t(model.pairs()[p].b)];
    if (a.entity == b.entity) {  // self-collision: the joints' straight line is not a motion
      rules[p] = PairRule::Ignored;
      continue;
    }
    for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      if (scene.system.entity(x.entity).kind == EntityKind::FloatingRobot &&
          stance_links.count({x.entity, x.link}) &&
          may_touch(scene, x.entity, x.link, y.entity, y.link, options.contact_pairs))
        rules[p] = PairRule::Ignored;
      if (scene.system.entity(x.entity).kind == EntityKind::FixedRobot &&
          scene.system.entity(y.entity).kind == EntityKind::Object && x.moves &&
          carries(scene, x.entity, y.entity, options.contact_pairs))
        rules[p] = PairRule::Ignored;
    }
  }
  return rules;
}

}  // namespace

GuideValidity::GuideValidity(const Problem& problem, const Eigen::VectorXd& q_start,
                             const Eigen::VectorXd& q_goal, const GuideOptions& options)
    : problem_(problem), options_(options) {
  const Scene& scene = problem.scene;
  const System& system = scene.system;
  for (int e = 0; e < system.num_entities(); ++e) data_.emplace_back(system.entity(e));
  if (scene.collision) {
    collision_data_.emplace_back(system, *scene.collision);
    std::vector<PairRule> rules = pair_rules(problem, options_);
    // A contact's links keep at least their depth at either end, less kTouchDepth (a palm
    // modelled into its handle); the others are left out when closer than the clearance there.
    std::vector<double> bound(rules.size(), options_.clearance);
    for (size_t p = 0; p < rules.size(); ++p)
      if (rules[p] == PairRule::Touch) bound[p] = -kTouchDepth;
    for (const Eigen::VectorXd* q : {&q_start, &q_goal}) {
      update(*q);
      for (size_t p = 0; p < rules.size(); ++p) {
        if (rules[p] == PairRule::Ignored) continue;
        const double d = signed_distance(*scene.collision, collision_data_[0], int(p)).distance;
        if (rules[p] == PairRule::Clearance && d < bound[p]) rules[p] = PairRule::Ignored;
        if (rules[p] == PairRule::Touch) bound[p] = std::min(bound[p], d - kTouchDepth);
      }
    }
    for (size_t p = 0; p < rules.size(); ++p)
      if (rules[p] != PairRule::Ignored) checked_pairs_.push_back({int(p), bound[p]});
  }
  if (scene.gravity.norm() == 0.0) return;
  for (int e = 0; e < system.num_entities(); ++e) {
    if (system.entity(e).kind != EntityKind::FloatingRobot) continue;
    robots_.push_back(e);
    for (int i = 0; i < int(scene.surfaces.of(e).size()); ++i)
      for (int f = 0; f < system.num_entities(); ++f)
        for (int j = 0; f != e && j < int(scene.surfaces.of(f).size()); ++j)
          if (offered(scene, {e, i}, {f, j}, options_.contact_pairs))
            supports_.push_back({e, {e, i}, {f, j}});
    // The stances' own contacts are supports too, offered or not (a robot whose feet are fixed
    // where they are: the contact pairs need not name them).
    for (const auto* stance : {&problem.initial_stance, &problem.goal_stance})
      for (const StanceContact& c : *stance)
        for (const auto& [own, other] :
             {std::pair{c.contact.s1, c.contact.s2}, std::pair{c.contact.s2, c.contact.s1}})
          if (own.entity == e && other.entity != e) supports_.push_back({e, own, other});
  }
}

void GuideValidity::update(const Eigen::VectorXd& q) {
  const System& system = problem_.scene.system;
  for (int e = 0; e < system.num_entities(); ++e)
    forward_kinematics(system.entity(e), q.segment(system.offset(e), system.entity(e).nq()),
                       data_[size_t(e)]);
  if (!collision_data_.empty()) collision_data_[0].update(*problem_.scene.collision, data_);
}

int GuideValidity::first_colliding_pair(double* distance) {
  const CollisionModel& model = *problem_.scene.collision;
  for (size_t k = 0; k < checked_pairs_.size(); ++k) {
    const auto [pair, bound] = checked_pairs_[k];
    if (distance_lower_bound(model, data_, pair) >= bound) continue;
    const double d = signed_distance(model, collision_data_[0], pair).distance;
    if (d < bound) {
      *distance = d;
      return int(k);
    }
  }
  return -1;
}

// Distance from s.own's origin to s.other's polygon (its plane within the polygon, else the edge).
double GuideValidity::support_distance(const Support& s) const {
  const Scene& scene = problem_.scene;
  const Surface& own = scene.surfaces.get(s.own);
  const Surface& other = scene.surfaces.get(s.other);
  const Eigen::Vector3d p_W =
      data_[size_t(s.own.entity)].T_WL[size_t(own.link)] * own.T_LS.translation();
  const Eigen::Isometry3d T_WS =
      data_[size_t(s.other.entity)].T_WL[size_t(other.link)] * other.T_LS;
  const Eigen::Vector3d p_S = T_WS.inverse() * p_W;
  const double outside = std::max(0.0, distance_outside(other.vertices_S, p_S.head<2>()));
  return std::hypot(outside, p_S.z());
}

int GuideValidity::first_unsupported_robot() const {
  for (int robot : robots_) {
    const bool supported = std::any_of(supports_.begin(), supports_.end(), [&](const Support& s) {
      return s.robot == robot && support_distance(s) <= options_.reach;
    });
    if (!supported) return robot;
  }
  return -1;
}

bool GuideValidity::valid(const Eigen::VectorXd& q) {
  update(q);
  double d = 0.0;
  if (!collision_data_.empty() && first_colliding_pair(&d) >= 0) return false;
  return first_unsupported_robot() < 0;
}

std::string GuideValidity::why_invalid(const Eigen::VectorXd& q) {
  update(q);
  std::ostringstream out;
  double d = 0.0;
  if (const int k = collision_data_.empty() ? -1 : first_colliding_pair(&d); k >= 0) {
    const auto [pair, bound] = checked_pairs_[size_t(k)];
    const CollisionPair& p = problem_.scene.collision->pairs()[size_t(pair)];
    out << collision_link_name(problem_.scene, p.a) << " - "
        << collision_link_name(problem_.scene, p.b) << " " << d << " m < " << bound << " m"
        << (bound < 0 ? " (a contact's links, touching)" : " (clearance)");
  } else if (const int robot = first_unsupported_robot(); robot >= 0) {
    out << problem_.scene.system.entity(robot).name << ": no contact-capable surface within "
        << options_.reach << " m of a support";
  }
  return out.str();
}

}  // namespace stanceplan
