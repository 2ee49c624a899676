#include "planner/guide/hand_over.h"

#include <algorithm>
#include <cmath>

#include "planner/guide/guide_validity.h"
#include "planner/model/kinematics.h"
#include "planner/solver/posture_solver.h"

namespace stanceplan {
namespace {

constexpr double kMoves = 0.01;       // m: an object that moves less needs no carrier
constexpr double kAntipodal = -0.99;  // cosine of the normals of two opposed facets
constexpr int kFacetPairsTried = 2;   // per carrier, the facet pairs most across its way
constexpr int kMaxSolves = 8;         // hand-over postures tried
constexpr int kHoldSolves = 4;        // grasps tried per end of a carrier that may carry it alone
constexpr int kHoldBudget = 30;       // their Ipopt iterations without progress (stall_monitor.h)
constexpr double kAlongStep = 0.02;   // of the straight way, searched for the hand-over point

// A surface's stretched chain (hand_over.h): where its first moving joint is and how far the
// surface reaches from there.
struct Reach {
  SurfaceRef surface;
  Eigen::Vector3d start_W;
  double length = 0.0;
};

Reach surface_reach(const Problem& problem, const std::vector<ModelData>& data, SurfaceRef ref) {
  const Surface& s = problem.scene.surfaces.get(ref);
  const Model& model = *problem.scene.system.entity(ref.entity).model;
  Reach reach{ref, data[size_t(ref.entity)].T_WL[size_t(s.link)].translation(), 0.0};
  for (const Eigen::Vector3d& v : s.vertices_L()) reach.length = std::max(reach.length, v.norm());
  double below = reach.length;  // the chain below the joint being looked at
  for (int l = s.link; l > 0; l = model.links[size_t(l)].parent_link) {
    const Joint& j = model.joints[size_t(model.links[size_t(l)].parent_joint)];
    if (j.type == JointType::Prismatic) below += std::max(std::abs(j.lower), std::abs(j.upper));
    if (j.movable()) {  // the chain from this joint's origin down
      reach.start_W = data[size_t(ref.entity)].T_WL[size_t(j.parent_link)] * j.T_PJ.translation();
      reach.length = below;
    }
    below += j.T_PJ.translation().norm();
  }
  return reach;
}

// How much a carrier's best surface has to spare reaching p (negative: out of reach).
double spare(const std::vector<Reach>& reaches, const Eigen::Vector3d& p_W) {
  double best = -INFINITY;
  for (const Reach& r : reaches) best = std::max(best, r.length - (p_W - r.start_W).norm());
  return best;
}

struct Carrier {
  int robot = -1;
  std::vector<Reach> reaches;  // its surfaces that may touch the object
};

std::vector<Carrier> carriers_of(const Problem& problem, const std::vector<ModelData>& data,
                                 int object, const GuideOptions& options) {
  const Scene& scene = problem.scene;
  std::vector<Carrier> carriers;
  for (int r = 0; r < scene.system.num_entities(); ++r) {
    if (scene.system.entity(r).kind != EntityKind::FixedRobot) continue;  // a floating one walks
    Carrier c{r, {}};
    for (int i = 0; i < int(scene.surfaces.of(r).size()); ++i)
      for (int j = 0; j < int(scene.surfaces.of(object).size()); ++j)
        if (offered(scene, {r, i}, {object, j}, options.contact_pairs)) {
          c.reaches.push_back(surface_reach(problem, data, {r, i}));
          break;
        }
    if (!c.reaches.empty()) carriers.push_back(c);
  }
  return carriers;
}

// One carrier's grasp: its surfaces a, b on the object's facets f, g.
struct Grasp {
  SurfaceRef a, b, f, g;
  double score = 0.0;  // how much the facets' normals lie across the carrier's way (1: all)
};

// The antipodal grasps of carrier c on the object at p_W, best first, kFacetPairsTried facet pairs
// in both assignments, leaving out the facets in `taken`.
std::vector<Grasp> grasps_of(const Problem& problem, const std::vector<ModelData>& data,
                             const Carrier& c, int object, const Eigen::Vector3d& p_W,
                             const GuideOptions& options, const std::vector<SurfaceRef>& taken) {
  const Scene& scene = problem.scene;
  const Reach& reach = c.reaches.front();
  Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(p_W - reach.start_W);
  across = across.norm() > 1e-9 ? across.normalized() : Eigen::Vector3d::UnitX();
  const auto normal_W = [&](SurfaceRef r) {
    return Eigen::Vector3d(
        data[size_t(r.entity)].T_WL[size_t(scene.surfaces.get(r).link)].linear() *
        scene.surfaces.get(r).normal_L());
  };
  const auto is_taken = [&](SurfaceRef r) {
    return std::any_of(taken.begin(), taken.end(), [&](SurfaceRef t) { return t == r; });
  };
  std::vector<Grasp> pairs;
  const int n = int(scene.surfaces.of(object).size());
  for (int f = 0; f < n; ++f)
    for (int g = f + 1; g < n; ++g) {
      const SurfaceRef rf{object, f}, rg{object, g};
      if (scene.surfaces.get(rf).is_point() || scene.surfaces.get(rg).is_point()) continue;
      if (is_taken(rf) || is_taken(rg) || normal_W(rf).dot(normal_W(rg)) > kAntipodal) continue;
      pairs.push_back({{}, {}, rf, rg, std::abs(normal_W(rf).dot(across))});
    }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const Grasp& x, const Grasp& y) { return x.score > y.score; });
  if (pairs.size() > size_t(kFacetPairsTried)) pairs.resize(size_t(kFacetPairsTried));
  std::vector<Grasp> grasps;
  for (const Grasp& p : pairs)
    for (size_t i = 0; i < c.reaches.size(); ++i)
      for (size_t j = 0; j < c.reaches.size(); ++j) {
        const SurfaceRef a = c.reaches[i].surface, b = c.reaches[j].surface;
        if (i == j || scene.surfaces.get(a).link == scene.surfaces.get(b).link) continue;
        if (!offered(scene, a, p.f, options.contact_pairs) ||
            !offered(scene, b, p.g, options.contact_pairs))
          continue;
        grasps.push_back({a, b, p.f, p.g, p.score});
      }
  return grasps;
}

void add_grasp(const Grasp& g, std::vector<StanceContact>& contacts) {
  contacts.push_back({Contact{g.a, g.f}, std::nullopt, "", 0});
  contacts.push_back({Contact{g.b, g.g}, std::nullopt, "", 0});
}

// The point of the straight way p0 -> p1 that both carriers reach with the most to spare.
Eigen::Vector3d hand_over_point(const Carrier& from, const Carrier& to, const Eigen::Vector3d& p0,
                                const Eigen::Vector3d& p1) {
  Eigen::Vector3d best = 0.5 * (p0 + p1);
  double most = -INFINITY;
  for (double t = 0.0; t <= 1.0 + 1e-9; t += kAlongStep) {
    const Eigen::Vector3d p = (1.0 - t) * p0 + t * p1;
    const double s = std::min(spare(from.reaches, p), spare(to.reaches, p));
    if (s > most) most = s, best = p;
  }
  return best;
}

// Both carriers grasping the object at p_W: the first solved of the grasps tried.
std::optional<HandOver> solve_hand_over(const Problem& problem, const std::vector<ModelData>& data,
                                        int object, const Carrier& from, const Carrier& to,
                                        const Eigen::Vector3d& p_W, const GuideOptions& options,
                                        std::string* note) {
  const PostureSolver solver(problem.scene, problem.solver);
  Eigen::VectorXd q = problem.initial_configuration;
  q.segment<3>(problem.scene.system.offset(object) + Entity::kBasePosition) = p_W;
  HandOver h{object, from.robot, to.robot, {}, {}, 0};
  std::string last;
  for (const Grasp& g0 : grasps_of(problem, data, from, object, p_W, options, {}))
    for (const Grasp& g1 : grasps_of(problem, data, to, object, p_W, options, {g0.f, g0.g})) {
      if (h.solves == kMaxSolves) break;
      std::vector<StanceContact> grasps;
      add_grasp(g0, grasps);
      add_grasp(g1, grasps);
      const PostureResult r = solver.solve(problem.loaded_request(grasps, q));
      ++h.solves;
      if (r.status == PostureStatus::Solved) {
        h.q = r.q;
        h.grasps = grasps;
        return h;
      }
      last = std::string(to_string(r.status)) + " (" + r.message + ")";
    }
  *note = "no hand-over posture: " + std::to_string(h.solves) + " grasps tried" +
          (last.empty() ? "" : ", the last " + last);
  return std::nullopt;
}

// The object's contacts of a stance with anything but a carrier (its support), placements left
// to the solver.
std::vector<StanceContact> supports_of(const Problem& problem,
                                       const std::vector<StanceContact>& stance, int object) {
  std::vector<StanceContact> supports;
  for (const StanceContact& c : stance) {
    const int a = c.contact.s1.entity, b = c.contact.s2.entity;
    if (a != object && b != object) continue;
    const EntityKind other = problem.scene.system.entity(a == object ? b : a).kind;
    if (other == EntityKind::Environment) supports.push_back({c.contact, std::nullopt, "", 0});
  }
  return supports;
}

// Whether carrier c can grasp the object where `q` puts it, on the supports it has there (a
// posture solved with one of its first grasps, every contact loaded). The reach bound is
// necessary, not sufficient: the dual arm's cylinder moved 2 cm towards arm 2 is within arm 2's
// stretched chain at both ends, yet no grasp of arm 2 holds it on platform A.
bool holds_at(const Problem& problem, const std::vector<ModelData>& data, const Carrier& c,
              int object, const Eigen::VectorXd& q, const std::vector<StanceContact>& supports,
              const GuideOptions& options) {
  const PostureSolver solver(problem.scene, problem.solver);
  const Eigen::Vector3d p_W =
      q.segment<3>(problem.scene.system.offset(object) + Entity::kBasePosition);
  int solves = 0;
  for (const Grasp& g : grasps_of(problem, data, c, object, p_W, options, {})) {
    if (solves++ == kHoldSolves) break;
    std::vector<StanceContact> contacts = supports;
    add_grasp(g, contacts);
    PostureRequest request = problem.loaded_request(contacts, q);
    request.progress_budget = kHoldBudget;  // a grasp out of reach stalls: stop it early
    if (solver.solve(request).status == PostureStatus::Solved) return true;
  }
  return false;
}

}  // namespace

std::optional<HandOver> find_hand_over(const Problem& problem, const Eigen::VectorXd& q_goal,
                                       const GuideOptions& options, std::string* note) {
  note->clear();
  const System& system = problem.scene.system;
  const std::vector<ModelData> data = system_kinematics(system, problem.initial_configuration);
  for (int o = 0; o < system.num_entities(); ++o) {
    if (system.entity(o).kind != EntityKind::Object) continue;
    const int at = system.offset(o) + Entity::kBasePosition;
    const Eigen::Vector3d p0 = problem.initial_configuration.segment<3>(at),
                          p1 = q_goal.segment<3>(at);
    if ((p1 - p0).norm() <= kMoves) continue;
    const std::vector<Carrier> carriers = carriers_of(problem, data, o, options);
    const Carrier* from = nullptr;
    const Carrier* to = nullptr;
    bool one_carries = false;
    for (const Carrier& c : carriers) {
      bool starts = spare(c.reaches, p0) >= 0.0, ends = spare(c.reaches, p1) >= 0.0;
      if (starts && ends) {  // within the bound at both ends: does it hold the object there?
        Eigen::VectorXd at_goal = problem.initial_configuration;  // the object as the goal has it
        at_goal.segment<7>(at) = q_goal.segment<7>(at);
        starts = holds_at(problem, data, c, o, problem.initial_configuration,
                          supports_of(problem, problem.initial_stance, o), options);
        ends = holds_at(problem, data, c, o, at_goal, supports_of(problem, problem.goal_stance, o),
                        options);
      }
      one_carries = one_carries || (starts && ends);
      if (starts && !from) from = &c;
      if (ends && !to) to = &c;
    }
    if (one_carries || !from || !to) continue;
    return solve_hand_over(problem, data, o, *from, *to, hand_over_point(*from, *to, p0, p1),
                           options, note);
  }
  return std::nullopt;
}

}  // namespace stanceplan
