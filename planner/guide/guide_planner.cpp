#include "planner/guide/guide_planner.h"

#include <chrono>
#include <sstream>

#include "planner/guide/goal_posture.h"
#include "planner/guide/guide_space.h"
#include "planner/guide/guide_validity.h"
#include "planner/guide/ompl_path.h"

namespace stanceplan {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string no_posture(const Problem& problem, const PostureResult& r) {
  std::ostringstream out;
  out << "guide: goal posture: no posture for the goal stance"
      << (problem.file.empty() ? "" : " of " + problem.file) << ": " << to_string(r.status) << " ("
      << r.message << ")";
  return out.str();
}

std::string no_path(const PlannedPath& path, GuideValidity& validity, const GuideSpace& space,
                    const GuideOptions& options) {
  std::ostringstream out;
  out << "guide: path: ";
  Eigen::VectorXd q;
  if (path.status == PathStatus::InvalidStart) {
    space.configuration(space.x_start(), q);
    out << "the initial configuration is not valid: " << validity.why_invalid(q);
  } else if (path.status == PathStatus::InvalidGoal) {
    space.configuration(space.x_goal(), q);
    out << "the goal posture is not valid: " << validity.why_invalid(q);
  } else {
    out << "no collision-free path from the initial to the goal configuration within "
        << options.time_limit << " s (clearance " << options.clearance << " m over "
        << validity.num_checked_pairs() << " collision pairs, a support within " << options.reach
        << " m)";
    // What blocks the straight way, a hint for the user (1 % steps).
    for (int k = 1; k < 100; ++k) {
      space.configuration(GuideSpace::between(space.x_start(), space.x_goal(), k / 100.0), q);
      if (const std::string why = validity.why_invalid(q); !why.empty()) {
        out << "; the straight way is blocked " << k << " % along: " << why;
        break;
      }
    }
  }
  return out.str();
}

}  // namespace

const char* to_string(GuideStatus status) {
  switch (status) {
    case GuideStatus::Computed:
      return "computed";
    case GuideStatus::NoGoalPosture:
      return "no goal posture";
    case GuideStatus::NoPath:
      return "no path";
  }
  return "?";
}

ComputedGuide compute_guide(const Problem& problem, const GuideOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ComputedGuide guide;
  const PostureResult posture = solve_goal_posture(problem);
  guide.posture_time_s = seconds_since(started);
  if (posture.status != PostureStatus::Solved) {
    guide.status = GuideStatus::NoGoalPosture;
    guide.message = no_posture(problem, posture);
    guide.time_s = seconds_since(started);
    return guide;
  }
  guide.q_goal = posture.q;
  const GuideSpace space(problem.scene.system, problem.initial_configuration, posture.q);
  GuideValidity validity(problem, space.q_start(), space.q_goal(), options);
  guide.checked_pairs = validity.num_checked_pairs();
  Eigen::VectorXd q(problem.scene.system.nq());
  const PlannedPath path = plan_guide_path(
      space,
      [&](const Eigen::VectorXd& x) {
        space.configuration(x, q);
        return validity.valid(q);
      },
      options);
  guide.path_time_s = path.time_s;
  guide.raw_waypoints = path.raw_waypoints;
  if (path.status != PathStatus::Found) {
    guide.status = GuideStatus::NoPath;
    guide.message = no_path(path, validity, space, options);
    guide.time_s = seconds_since(started);
    return guide;
  }
  for (const Eigen::VectorXd& x : path.waypoints) {
    space.configuration(x, q);
    guide.path.push_back(q);
  }
  for (const Eigen::VectorXd& x : points_along(space, path.waypoints, options.spacing)) {
    guide.milestones.push_back(milestone_at(space, x));
    space.configuration(x, q);
    guide.milestone_configurations.push_back(q);
  }
  guide.status = GuideStatus::Computed;
  guide.time_s = seconds_since(started);
  return guide;
}

}  // namespace stanceplan
