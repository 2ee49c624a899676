#pragma once
// A collision-free path through a GuideSpace with OMPL's RRT-Connect (the only file that includes
// OMPL, as planner/solver/ipopt_adapter.cpp is for Ipopt), then shortened. Deterministic for a
// seed: the samples come from our own generator seeded with GuideOptions::seed (OMPL's global seed
// is also set, once per process, before any planner exists), and neither the planner nor the
// shortcut draws from OMPL's own generators.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "planner/guide/guide_options.h"
#include "planner/guide/guide_space.h"

namespace stanceplan {

enum class PathStatus { Found, InvalidStart, InvalidGoal, NoPath };

struct PlannedPath {
  PathStatus status = PathStatus::NoPath;
  std::vector<Eigen::VectorXd> waypoints;  // points of the space, start to goal, after shortcuts
  int raw_waypoints = 0;                   // before the shortcuts
  // The planner's state-validity checks, at most GuideOptions::max_checks (the ends' checks before
  // it and the shortcuts' after it not counted): the same for the same inputs on any machine,
  // unlike time_s.
  std::int64_t checks = 0;
  double time_s = 0.0;
};

// `valid(x)`: whether the space's configuration at x may be on the path. Poses of the moving
// roots are sampled near the box spanned by their start and goal positions (robots within 0.5 m,
// 0.1 m vertically; objects within their move's length, 5-50 cm); robots' trunks within
// GuideOptions::max_tilt of their initial roll and pitch, any heading; objects near their turn
// from start to goal orientation (within 0.5 rad). Motions are checked every 2 cm (metres plus
// radians of the space's distance), or every tenth of the whole move when shorter (5 mm at least).
// The planner gets GuideOptions::max_checks calls of `valid` and no more (NoPath without a path
// within them), and no wall-clock limit: where it stops is the same on any machine.
PlannedPath plan_guide_path(const GuideSpace& space,
                            const std::function<bool(const Eigen::VectorXd&)>& valid,
                            const GuideOptions& options);

}  // namespace stanceplan
