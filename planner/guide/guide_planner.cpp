#include "planner/guide/guide_planner.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>

#include "planner/guide/approach.h"
#include "planner/guide/goal_posture.h"
#include "planner/guide/guide_space.h"
#include "planner/guide/guide_validity.h"
#include "planner/guide/hand_over.h"
#include "planner/guide/ompl_path.h"
#include "planner/guide/posture_stages.h"

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
        << options.max_checks << " validity checks (search.guide_max_checks; clearance "
        << options.clearance << " m over " << validity.num_checked_pairs()
        << " collision pairs, a support within " << options.reach << " m)";
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

ComputedGuide& failed(std::chrono::steady_clock::time_point started, ComputedGuide& guide) {
  guide.status = GuideStatus::NoPath;
  guide.time_s = seconds_since(started);
  return guide;
}

// The approach (approach.h) nearest the goal's footholds that is valid where the whole path's
// ends are: backed off by 0, 2, 4 ... cm, in the initial posture, else with the goal posture's
// arms. None when no such one is valid (the note says why, at the footholds).
std::optional<Approach> valid_approach(const Problem& problem, const Eigen::VectorXd& q_goal,
                                       const GuideOptions& options, ComputedGuide& guide) {
  if (!approach_configuration(problem, q_goal)) return std::nullopt;
  GuideValidity whole(problem, problem.initial_configuration, q_goal, options);
  for (int k = 0; k * kBackOffStep <= kMaxBackOff + 1e-9; ++k)
    for (const bool limbs_only : {false, true}) {
      std::optional<Approach> a =
          approach_configuration(problem, q_goal, limbs_only, k * kBackOffStep);
      if (whole.valid(a->q)) return a;
    }
  guide.approach_note = "no valid approach configuration (at the goal's footholds: " +
                        whole.why_invalid(approach_configuration(problem, q_goal)->q) +
                        "): one leg";
  return std::nullopt;
}

// One leg of the path, q_a to q_b: its waypoints and milestones appended to the guide (false, with
// the message, when no path is found). The milestones are spaced along the path, or at its
// corners only (`at_corners`: the waypoints after the shortcuts, the last one its end).
bool plan_leg(const Problem& problem, const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b,
              const GuideOptions& options, ComputedGuide& guide, bool at_corners = false) {
  const GuideSpace space(problem.scene.system, q_a, q_b);
  GuideValidity validity(problem, space.q_start(), space.q_goal(), options);
  guide.checked_pairs = std::max(guide.checked_pairs, validity.num_checked_pairs());
  Eigen::VectorXd q(problem.scene.system.nq());
  const PlannedPath path = plan_guide_path(
      space,
      [&](const Eigen::VectorXd& x) {
        space.configuration(x, q);
        return validity.valid(q);
      },
      options);
  guide.path_time_s += path.time_s;
  guide.raw_waypoints += path.raw_waypoints;
  guide.leg_checks.push_back(path.checks);
  if (path.status != PathStatus::Found) {
    guide.message = no_path(path, validity, space, options);
    return false;
  }
  for (size_t k = guide.path.empty() ? 0 : 1; k < path.waypoints.size(); ++k) {
    space.configuration(path.waypoints[k], q);
    guide.path.push_back(q);
  }
  const std::vector<Eigen::VectorXd> points =
      at_corners ? std::vector<Eigen::VectorXd>(path.waypoints.begin() + 1, path.waypoints.end())
                 : points_along(space, path.waypoints, options.spacing);
  for (const Eigen::VectorXd& x : points) {
    guide.milestones.push_back(milestone_at(space, x));
    space.configuration(x, q);
    guide.milestone_configurations.push_back(q);
  }
  return true;
}

// The approach's milestones offer the kept contacts only, and an approaching robot's base keeps
// the height it has over them (its kept contacts stay on the surfaces they start on): evenly
// from the initial height to the approach's, not the path's samples' (which wander 0.1 m up and
// down, the tolerance of a milestone). The last one, where the robot stands to change its
// posture, states the approach's heading: reached turned, the robot sits down askew (the
// guide-free desk started 2 cm to its left: its feet 0.1 rad off, no plan).
void walk_level(const Problem& problem, const Approach& approach, ComputedGuide& guide) {
  const System& system = problem.scene.system;
  std::vector<GuideMilestone>& milestones = guide.milestones;
  for (size_t k = 0; k < milestones.size(); ++k) {
    milestones[k].contacts = approach.kept;
    const double t = double(k + 1) / double(milestones.size());
    for (GuideMilestone::Root& root : milestones[k].roots)
      if (std::find(approach.robots.begin(), approach.robots.end(), root.entity) !=
          approach.robots.end()) {
        const int z = system.offset(root.entity) + Entity::kBasePosition + 2;
        root.position.z() = (1.0 - t) * problem.initial_configuration[z] + t * approach.q[z];
        guide.milestone_configurations[k][z] = root.position.z();
        if (k + 1 == milestones.size()) {
          const int w = system.offset(root.entity) + Entity::kBaseQuaternion;
          root.rpy = base_rpy(approach.q.segment<4>(w));
          guide.milestone_configurations[k].segment<4>(w) = approach.q.segment<4>(w);
        }
      }
  }
}

// The goal milestone states the robots' joints of the goal posture: the solver's reference there
// is then the posture the goal stance was solved in, not the initial one carried along (a robot
// sitting down is otherwise pulled towards its standing legs).
void state_goal_joints(const System& system, const Eigen::VectorXd& q_goal, GuideMilestone& goal) {
  for (GuideMilestone::Root& root : goal.roots) {
    const Entity& entity = system.entity(root.entity);
    if (entity.kind != EntityKind::FloatingRobot || entity.model->num_dofs() == 0) continue;
    root.joints =
        q_goal.segment(system.offset(root.entity) + entity.first_dof(), entity.model->num_dofs());
  }
}

// An object's milestones state its orientation only when the task turns it (its goal orientation
// differs from the initial one): the hand-over posture's tilt (0.25 rad for the dual arm's
// cylinder) is one grasp's, not the task's, and stated it pulls every node towards it.
void state_task_turns_only(const Problem& problem, const Eigen::VectorXd& q_goal,
                           ComputedGuide& guide) {
  const GuideSpace whole(problem.scene.system, problem.initial_configuration, q_goal);
  for (GuideMilestone& m : guide.milestones)
    for (GuideMilestone::Root& root : m.roots)
      if (!whole.turns(root.entity)) root.rpy.reset();
}

// The contacts the milestones offer around a hand-over: the carriers' grasping surfaces (those of
// the grasps found for it) on every surface of the object the contact pairs allow (a held object
// moves by regrasps), and the object's contacts of the initial and goal stances (lifted, put
// down), not every surface of the object on every surface of the environment, a branching the
// hand-over needs none of (the guide-free dual arm with every pair offered: a plan in 3014 solver
// calls, 284 s, against a hand-guided 348).
void offer_grasps(const Problem& problem, const GuideOptions& options, const HandOver& hand_over,
                  ComputedGuide& guide) {
  const Scene& scene = problem.scene;
  std::vector<std::pair<std::string, std::string>> offers;
  const auto offer = [&](SurfaceRef a, SurfaceRef b) {
    std::pair<std::string, std::string> p{scene.surfaces.id(scene.system, a),
                                          scene.surfaces.id(scene.system, b)};
    if (std::find(offers.begin(), offers.end(), p) == offers.end()) offers.push_back(p);
  };
  const int facets = int(scene.surfaces.of(hand_over.object).size());
  for (const StanceContact& g : hand_over.grasps) {
    std::vector<int> on;
    for (int j = 0; j < facets; ++j)
      if (offered(scene, g.contact.s1, {hand_over.object, j}, options.contact_pairs))
        on.push_back(j);
    if (int(on.size()) == facets) {  // written as "pad on object/*"
      const std::pair<std::string, std::string> p{
          scene.surfaces.id(scene.system, g.contact.s1),
          scene.system.entity(hand_over.object).name + "/*"};
      if (std::find(offers.begin(), offers.end(), p) == offers.end()) offers.push_back(p);
      continue;
    }
    for (int j : on) offer(g.contact.s1, {hand_over.object, j});
  }
  for (const auto* stance : {&problem.initial_stance, &problem.goal_stance})
    for (const StanceContact& c : *stance) offer(c.contact.s1, c.contact.s2);
  for (GuideMilestone& m : guide.milestones) m.contacts = offers;
}

// A stage's milestone (posture_stages.h): the roots of the milestones before it at the stage's
// whole posture, position, heading and a robot's joints (the solver's reference there is the
// stage's posture: a robot that crouches is not pulled towards its standing legs; and a node
// turned from it is not the stage: without the heading, the guide-free desk's crouch counted as
// reached with the feet turned by 0.04-0.42 rad, and the first thigh landed askew in the middle of
// the seat, leaving no room for the second), and the stage's contacts offered.
void append_stage(const System& system, const PostureStage& stage, ComputedGuide& guide) {
  GuideMilestone m;
  m.roots = guide.milestones.back().roots;
  for (GuideMilestone::Root& root : m.roots) {
    const int o = system.offset(root.entity);
    root.position = stage.q.segment<3>(o + Entity::kBasePosition);
    root.rpy = base_rpy(stage.q.segment<4>(o + Entity::kBaseQuaternion));
  }
  state_goal_joints(system, stage.q, m);
  m.contacts = stage.offered;
  guide.milestones.push_back(m);
  guide.milestone_configurations.push_back(stage.q);
  guide.path.push_back(stage.q);
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
  guide.phases = order_goal_contacts(problem, posture);
  // An object that one robot cannot carry all the way is handed over (hand_over.h): the path
  // passes through the posture where both robots hold it.
  if (const std::optional<HandOver> hand_over =
          find_hand_over(problem, posture.q, options, &guide.hand_over_note)) {
    guide.hand_over_solves = hand_over->solves;
    // Milestones at the legs' corners only: a held object moves by regrasps, each pulled by the
    // milestone aimed at, and milestones between on a straight way only hold it back (the
    // guide-free dual arm: 1087 solver calls with one every 0.3 m, 715 with the hand-over's and
    // the goal's alone).
    if (!plan_leg(problem, problem.initial_configuration, hand_over->q, options, guide, true))
      return failed(started, guide);
    guide.hand_over_milestone = int(guide.milestones.size());
    if (!plan_leg(problem, hand_over->q, posture.q, options, guide, true))
      return failed(started, guide);
    state_task_turns_only(problem, posture.q, guide);
    offer_grasps(problem, options, *hand_over, guide);
    guide.status = GuideStatus::Computed;
    guide.time_s = seconds_since(started);
    return guide;
  }
  // On the way to a changed posture the robot first walks in its own (approach.h), when the
  // approach configuration is valid where the whole path's ends are; it then changes its posture
  // in stages where they solve (posture_stages.h), standing where the first stage (the crouch)
  // has its feet, else along one more leg of the path.
  std::optional<Approach> approach = valid_approach(problem, posture.q, options, guide);
  std::vector<PostureStage> stages;
  if (approach) {
    stages = posture_stages(problem, posture.q, guide.phases, &guide.stage_solves);
    if (!stages.empty())
      if (std::optional<Approach> a = valid_approach(problem, stages.front().q, options, guide))
        approach = a;
  }
  const Eigen::VectorXd& q_end_of_first = approach ? approach->q : posture.q;
  if (!plan_leg(problem, problem.initial_configuration, q_end_of_first, options, guide))
    return failed(started, guide);
  if (approach) {
    walk_level(problem, *approach, guide);
    guide.approach_milestones = int(guide.milestones.size());
    guide.approach_back_off = approach->back_off;
    for (const PostureStage& stage : stages) append_stage(problem.scene.system, stage, guide);
    guide.stages = int(stages.size());
    if (stages.empty() && !plan_leg(problem, approach->q, posture.q, options, guide))
      return failed(started, guide);
  }
  // The stages state their own joints; else the goal milestone states the goal posture's.
  if (!stages.empty())
    guide.q_goal = stages.back().q;
  else
    state_goal_joints(problem.scene.system, posture.q, guide.milestones.back());
  guide.status = GuideStatus::Computed;
  guide.time_s = seconds_since(started);
  return guide;
}

}  // namespace stanceplan
