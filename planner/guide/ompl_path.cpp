// The only file that includes OMPL (planner/CMakeLists.txt gives its headers to this file alone).
#include "planner/guide/ompl_path.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <random>

namespace stanceplan {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

// x (GuideSpace's layout) <-> an OMPL state of [SE(3) per moving root, R^1 phase].
void to_x(const ob::State* state, Eigen::VectorXd& x) {
  const auto* c = state->as<ob::CompoundState>();
  const int roots = int(x.size() - 1) / 7;
  for (int k = 0; k < roots; ++k) {
    const auto* se3 = c->as<ob::SE3StateSpace::StateType>(k);
    const auto& r = se3->rotation();
    x.segment<7>(7 * k) << se3->getX(), se3->getY(), se3->getZ(), r.w, r.x, r.y, r.z;
  }
  x[x.size() - 1] = c->as<ob::RealVectorStateSpace::StateType>(roots)->values[0];
}

void from_x(const Eigen::VectorXd& x, ob::State* state) {
  auto* c = state->as<ob::CompoundState>();
  const int roots = int(x.size() - 1) / 7;
  for (int k = 0; k < roots; ++k) {
    auto* se3 = c->as<ob::SE3StateSpace::StateType>(k);
    se3->setXYZ(x[7 * k], x[7 * k + 1], x[7 * k + 2]);
    const Eigen::Vector4d q = x.segment<4>(7 * k + 3).normalized();
    auto& r = se3->rotation();
    r.w = q[0], r.x = q[1], r.y = q[2], r.z = q[3];
  }
  c->as<ob::RealVectorStateSpace::StateType>(roots)->values[0] = x[x.size() - 1];
}

struct Box {
  Eigen::Vector3d low, high;
};

// Samples from our own generator (GuideOptions::seed): positions uniform in each root's box,
// robots' headings uniform with their trunk within max_tilt of the initial roll and pitch, objects
// uniform in SO(3) (Shoemake), the phase uniform.
class GuideSampler : public ob::StateSampler {
 public:
  GuideSampler(const ob::StateSpace* space, const GuideSpace& guide, std::vector<Box> boxes,
               const GuideOptions& options)
      : ob::StateSampler(space),
        guide_(guide),
        boxes_(std::move(boxes)),
        options_(options),
        rng_(options.seed),
        x_(guide.size()),
        y_(guide.size()) {}

  void sampleUniform(ob::State* state) override {
    const System& system = guide_.system();
    for (size_t k = 0; k < boxes_.size(); ++k) {
      const int e = guide_.moving()[k];
      for (int i = 0; i < 3; ++i) x_[7 * int(k) + i] = uniform(boxes_[k].low[i], boxes_[k].high[i]);
      const int o = system.offset(e) + Entity::kBaseQuaternion;
      x_.segment<4>(7 * int(k) + 3) =
          system.entity(e).kind == EntityKind::FloatingRobot
              ? upright(guide_.q_start().segment<4>(o))
              : near_the_turn(guide_.q_start().segment<4>(o), guide_.q_goal().segment<4>(o));
    }
    x_[x_.size() - 1] = uniform(0.0, 1.0);
    from_x(x_, state);
  }
  // Towards a uniform sample, at most `distance` away from `near` (not used by RRT-Connect).
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    sampleUniform(state);
    const double d = space_->distance(near, state);
    if (d > distance) space_->interpolate(near, state, distance / d, state);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) override {
    sampleUniformNear(state, mean, std::abs(std::normal_distribution<double>(0, stdDev)(rng_)));
  }

 private:
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }

  Eigen::Vector4d upright(const Eigen::Vector4d& wxyz0) {
    const Eigen::Quaterniond q0(wxyz0[0], wxyz0[1], wxyz0[2], wxyz0[3]);
    const Eigen::Matrix3d R0 = q0.normalized().toRotationMatrix();
    const double yaw0 = std::atan2(R0(1, 0), R0(0, 0));
    const double axis = uniform(-M_PI, M_PI), tilt = uniform(0.0, options_.max_tilt);
    const Eigen::Quaterniond q =
        Eigen::AngleAxisd(uniform(-M_PI, M_PI), Eigen::Vector3d::UnitZ()) *
        Eigen::AngleAxisd(tilt, Eigen::Vector3d(std::cos(axis), std::sin(axis), 0.0)) *
        Eigen::AngleAxisd(-yaw0, Eigen::Vector3d::UnitZ()) * q0.normalized();
    return {q.w(), q.x(), q.y(), q.z()};
  }

  // An object's orientation on its way from start to goal (a random point of the shortest turn)
  // turned by up to kObjectWobble about a random axis: an object held in a hand has little room.
  Eigen::Vector4d near_the_turn(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
    const Eigen::Quaterniond qa(a[0], a[1], a[2], a[3]), qb(b[0], b[1], b[2], b[3]);
    const Eigen::Vector3d axis = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    const Eigen::Quaterniond q = qa.normalized().slerp(uniform(0, 1), qb.normalized()) *
                                 Eigen::AngleAxisd(uniform(0, kObjectWobble), axis.normalized());
    return {q.w(), q.x(), q.y(), q.z()};
  }
  static constexpr double kObjectWobble = 0.5;  // rad

  const GuideSpace& guide_;
  std::vector<Box> boxes_;
  GuideOptions options_;
  std::mt19937 rng_;
  Eigen::VectorXd x_, y_;
};

// The path planner's budget (GuideOptions::max_checks) in the validity checks it makes: a counter,
// not a clock, so that a run ends at the same check on any machine. Past the budget every check
// fails (no tree grows, no trees connect) until the planner stops at its next iteration: a path is
// found within the budget or not at all, even by an iteration that would have run past it (the
// stairs' one iteration takes 329 checks). RRT-Connect checks from the thread that calls solve()
// only: plain integers.
struct CheckBudget {
  static constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  std::int64_t checks = 0;
  std::int64_t limit = kNone;
  bool spend() {
    if (checks >= limit) return false;
    ++checks;
    return true;
  }
};

std::vector<Box> sampling_boxes(const GuideSpace& guide) {
  std::vector<Box> boxes;
  for (int e : guide.moving()) {
    const int o = guide.system().offset(e);
    const Eigen::Vector3d a = guide.q_start().segment<3>(o), b = guide.q_goal().segment<3>(o);
    const bool robot = guide.system().entity(e).kind == EntityKind::FloatingRobot;
    // An object's room scales with its move (a pen slid 5 cm through a hand), within 5-50 cm.
    const double room = std::clamp((b - a).norm(), 0.05, 0.5);
    const Eigen::Vector3d margin =
        robot ? Eigen::Vector3d(0.5, 0.5, 0.1) : Eigen::Vector3d::Constant(room);
    boxes.push_back({a.cwiseMin(b) - margin, a.cwiseMax(b) + margin});
  }
  return boxes;
}

std::shared_ptr<ob::CompoundStateSpace> make_space(const std::vector<Box>& boxes) {
  auto space = std::make_shared<ob::CompoundStateSpace>();
  for (const Box& box : boxes) {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    ob::RealVectorBounds bounds(3);
    for (int i = 0; i < 3; ++i) bounds.setLow(i, box.low[i]), bounds.setHigh(i, box.high[i]);
    se3->setBounds(bounds);
    space->addSubspace(se3, 1.0);
  }
  auto phase = std::make_shared<ob::RealVectorStateSpace>(1);
  phase->setBounds(0.0, 1.0);
  space->addSubspace(phase, 1.0);
  return space;
}

// Greedy shortcuts: from each kept waypoint, straight to the farthest later one it sees.
std::vector<Eigen::VectorXd> shortcut(const ob::SpaceInformation& si,
                                      const std::vector<ob::State*>& states, int size) {
  std::vector<Eigen::VectorXd> out;
  Eigen::VectorXd x(size);
  for (size_t i = 0; i < states.size();) {
    to_x(states[i], x);
    out.push_back(x);
    if (i + 1 == states.size()) break;
    size_t j = states.size() - 1;
    while (j > i + 1 && !si.checkMotion(states[i], states[j])) --j;
    i = j;
  }
  return out;
}

}  // namespace

PlannedPath plan_guide_path(const GuideSpace& guide,
                            const std::function<bool(const Eigen::VectorXd&)>& valid,
                            const GuideOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  static std::once_flag seeded;
  std::call_once(seeded, [&] {
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ompl::RNG::setSeed(options.seed);
  });
  PlannedPath out;
  const std::vector<Box> boxes = sampling_boxes(guide);
  const auto space = make_space(boxes);
  space->setStateSamplerAllocator([&](const ob::StateSpace* s) -> ob::StateSamplerPtr {
    return std::make_shared<GuideSampler>(s, guide, boxes, options);
  });
  auto si = std::make_shared<ob::SpaceInformation>(space);
  CheckBudget budget;
  si->setStateValidityChecker([&, x = Eigen::VectorXd(guide.size())](const ob::State* s) mutable {
    if (!budget.spend()) return false;
    to_x(s, x);
    return valid(x);
  });
  // Motions checked every 2 cm, or every tenth of the whole move when that is shorter (5 mm at
  // least): a pen slid through a hand needs finer checks than a walk.
  const double step = std::clamp(0.1 * guide.travel(guide.x_start(), guide.x_goal()), 0.005, 0.02);
  si->setStateValidityCheckingResolution(step / space->getMaximumExtent());
  si->setup();
  ob::ScopedState<> start(space), goal(space);
  from_x(guide.x_start(), start.get());
  from_x(guide.x_goal(), goal.get());
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  if (!si->isValid(start.get())) out.status = PathStatus::InvalidStart;
  if (out.status == PathStatus::NoPath && !si->isValid(goal.get()))
    out.status = PathStatus::InvalidGoal;
  if (out.status != PathStatus::NoPath) {
    out.time_s = elapsed();
    return out;
  }
  auto problem = std::make_shared<ob::ProblemDefinition>(si);
  problem->setStartAndGoalStates(start, goal, 1e-6);
  og::RRTConnect planner(si);
  planner.setNearestNeighbors<ompl::NearestNeighborsLinear>();  // exact, draws no random numbers
  planner.setProblemDefinition(problem);
  planner.setup();
  // The budget counts the planner's checks alone (not the ends' above, nor the shortcuts'). The
  // condition has no period: the planner evaluates it itself, between its iterations.
  budget = {0, options.max_checks};
  const ob::PlannerStatus status =
      planner.solve(ob::PlannerTerminationCondition([&] { return budget.checks >= budget.limit; }));
  out.checks = budget.checks;
  budget.limit = CheckBudget::kNone;
  if (status == ob::PlannerStatus::EXACT_SOLUTION) {
    auto& path = *problem->getSolutionPath()->as<og::PathGeometric>();
    out.raw_waypoints = int(path.getStateCount());
    out.waypoints = shortcut(*si, path.getStates(), guide.size());
    out.status = PathStatus::Found;
  }
  out.time_s = elapsed();
  return out;
}

}  // namespace stanceplan
