#include "planner/motion/step_motion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "planner/motion/configuration_path.h"
#include "planner/motion/stance_rrt.h"

namespace stanceplan {
namespace {

// The two steps hold sigma at the same placements (both configurations realise it, E10-E13):
// beyond these, the plan's steps do not join.
constexpr double kPlacementTolerance = 1e-3;  // m
constexpr double kAngleTolerance = 1e-2;      // rad
// Every interpolation step aims at this fraction of the spacing: projections move points a
// little more than the reference does. With each step scaled by what the last one measured, 0.9
// rather than 0.8 (the pen: 399 -> 374 projections, 367 -> 334 samples; the table 2982 -> 2893,
// 1103 -> 1007).
constexpr double kFirstStepFraction = 0.9;
// A projection that still lands too far after this many halvings has jumped (the reference moved
// little, the solution a lot): the jump is bridged rather than halved further.
constexpr int kHalvingsBeforeBridge = 2;
// A halved step that still lands too far, at more than this fraction of the distance the step
// twice as long landed at, has jumped too: bridged at once
// (halving a smooth projection's step about halves the distance). The climb's step 2: the
// travel's projection jumps 4.4-4.6 spacings at s = 0.79 whatever the step.
constexpr double kJumpRatio = 0.75;
// A bridge may bridge once: the bridge of the climb's step 2 meets a jump of its own (1.14
// spacings, whatever the step); without it, the travel crept towards its jump bridging again and
// again (step 2: 78 -> 50 projections with both).
constexpr int kMaxBridgeDepth = 2;

std::string fixed3(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

double angle_between(double a, double b) {
  return std::abs(std::remainder(a - b, 2.0 * M_PI));
}

}  // namespace

namespace {
SolverOptions projection_options(const SolverOptions& plan, const MotionOptions& motion) {
  SolverOptions out = plan;
  out.w_configuration *= motion.reference_weight;  // E22 dominates E23-E24
  // A warm projection converges in a few iterations; one that has not in 30 rarely does (and
  // failing samples are what a step's time is spent on: they are retried closer).
  out.max_iterations = std::min(out.max_iterations, 30);
  // The objective is only E22 (and E23-E24) weighted 1000 times: a dual infeasibility of 1e-2 is a
  // configuration about 1e-5 rad from the nearest point to the reference, well inside the spacing
  // every sample is checked against; the constraints keep their tolerances (constr_viol_tol,
  // compl_inf_tol). Measured (iterations of the same projections): pen 1446 -> 1274, table
  // 14410 -> 13180, same solves, samples and certification.
  out.optimality_tolerance = std::max(out.optimality_tolerance, 1e-2);
  // Complementarity likewise: a bound held at s z <= 1e-3 rather than 1e-4 sits a little farther
  // inside its feasible side (an interior point never leaves it), and Ipopt stops at the first
  // iterate acceptable at ten times these tolerances (acceptable_iter 1; feasibility stays at
  // constr_viol_tol). Measured on the climb: 1022 -> 1019 projections, 3908 -> 3748 iterations.
  out.complementarity_tolerance = std::max(out.complementarity_tolerance, 1e-3);
  // Each sample starts next to its solution (the previous sample): a small, fixed barrier and
  // starting points left where they are. Measured on the walk's 22 steps (same 959 solves): median
  // 231 -> 162 ms per step, p95 1012 -> 543 ms, against Ipopt's adaptive barrier from 0.1.
  out.ipopt_options.insert(out.ipopt_options.begin(), {{"mu_strategy", "monotone"},
                                                       {"mu_init", "1e-6"},
                                                       {"bound_push", "1e-8"},
                                                       {"bound_frac", "1e-8"}});
  // Fixed costs of every solve, which a warm projection's few iterations do not amortise (perf,
  // the table's motion). constr_mult_init_max 0: the constraint multipliers start at zero instead
  // of Ipopt's least-squares estimate, which costs a factorization of its own (and its symbolic
  // analysis), a third of the Ipopt time; from a warm start the estimate barely helps (the same
  // iterations: pen 1274, table 13285 -> 13020; samples within 1e-10). MUMPS without its
  // permutation to a large diagonal and its scaling (both computed anew for every matrix, these
  // KKT systems have 130-300 rows): table 16.5 -> 12.9 s CPU, the same 13020 iterations,
  // samples within 1e-7.
  // Bound multipliers start at mu_init / slack (mu-based) instead of 1: with 1, a force of 100 N
  // starts 1e8 times off its complementarity mu = 1e-6 and the fraction-to-the-boundary rule
  // takes 3-5 iterations to bring the multipliers down; mu-based starts on the central path of
  // the fixed barrier, and most projections end after 2 iterations (the constraints' Newton
  // steps). Measured: climb 6371 -> 4646 iterations, table 13020 -> 10823, pen 1274 -> 1220.
  out.ipopt_options.insert(out.ipopt_options.begin() + 4, {{"constr_mult_init_max", "0.0"},
                                                           {"mumps_permuting_scaling", "0"},
                                                           {"mumps_scaling", "0"},
                                                           {"bound_mult_init_method", "mu-based"},
                                                           {"acceptable_iter", "1"}});
  return out;
}

// The retry of a sample the fast projection did not solve: the plan's own objective weights,
// Ipopt's adaptive barrier from its default start and at least 100 iterations. A warm start at the
// margin of a bound (a collision pair at its margin, a force at the cone's edge) can stall the
// small fixed barrier, and a reference deep inside an obstacle, weighted 1000 times, can keep the
// iterates from the feasible side; with the plan's weight E20 holds and the sample lands beside
// the obstacle, near the reference.
SolverOptions retry_options(const SolverOptions& plan) {
  SolverOptions out = plan;
  out.max_iterations = std::max(out.max_iterations, 100);
  return out;
}
}  // namespace

StepMotionPlanner::StepMotionPlanner(const Scene& scene, const SolverOptions& solver,
                                     MotionOptions options)
    : scene_(scene),
      solver_(scene, projection_options(solver, options)),
      retry_solver_(scene, retry_options(solver)),
      options_(options) {
  const std::string bad = check_motion_options(options_);
  if (!bad.empty()) throw std::invalid_argument("motion options: " + bad);
  q_ref_.resize(scene.system.nq());
}

double StepMotionPlanner::LinkPath::length() const {
  return std::hypot(to.x - from.x, to.y - from.y, h_to - h_from);
}

Placement StepMotionPlanner::LinkPath::placement_at(double s) const {
  const double turn = std::remainder(to.theta - from.theta, 2.0 * M_PI);
  return {from.x + s * (to.x - from.x), from.y + s * (to.y - from.y), from.theta + s * turn};
}

StepMotionPlanner::LinkPath StepMotionPlanner::LinkPath::part(double s0, double s1) const {
  LinkPath out = *this;
  out.from = placement_at(s0);
  out.to = placement_at(s1);
  out.h_from = h_from + s0 * (h_to - h_from);
  out.h_to = h_from + s1 * (h_to - h_from);
  return out;
}

StepMotionPlanner::LinkPath StepMotionPlanner::lift_path(const Contact& contact,
                                                         const Eigen::VectorXd& q) const {
  const ContactTask task = lift_task(contact, q);
  return {task, *task.placement, *task.placement, 0.0, options_.clearance};
}

ContactTask StepMotionPlanner::lift_task(const Contact& contact, const Eigen::VectorXd& q) const {
  ContactTask task;
  task.contact = contact;
  task.loaded = false;
  task.placement = measure_placement(scene_, contact, q);
  return task;
}

bool StepMotionPlanner::set_up(const PlanStep& a, const PlanStep& b, StepMotion* motion) {
  const auto disagree = [&](const std::string& why) {
    motion->status = MotionStatus::EndsDisagree;
    motion->message = why;
    return false;
  };
  request_.contacts.clear();
  request_.approaching.clear();
  for (const Contact& c : a.stance.contacts()) {
    const std::string name =
        scene_.surfaces.id(scene_.system, c.s1) + "-" + scene_.surfaces.id(scene_.system, c.s2);
    const bool touched =
        std::any_of(b.contacts.begin(), b.contacts.end(),
                    [&](const PlanContact& p) { return p.contact.same_surfaces(c); });
    if (!touched) return disagree("the next step does not touch " + name);
    ContactTask task = lift_task(c, a.q);
    task.loaded = true;
    const Placement p_b = measure_placement(scene_, c, b.q);
    const double moved = std::hypot(p_b.x - task.placement->x, p_b.y - task.placement->y);
    const double turned = angle_between(p_b.theta, task.placement->theta);
    if (moved > kPlacementTolerance || turned > kAngleTolerance)
      return disagree(name + " is not at the same placement in both steps (moved " + fixed3(moved) +
                      " m, turned " + fixed3(turned) + " rad)");
    request_.contacts.push_back(std::move(task));
  }
  held_ = int(request_.contacts.size());
  std::vector<SurfaceRef> surfaces;
  for (const PlanStep* step : {&a, &b})
    for (const PlanContact& pc : step->contacts) {
      surfaces.push_back(pc.contact.s1);
      surfaces.push_back(pc.contact.s2);
    }
  spacing_.emplace(scene_, surfaces);
  return true;
}

PostureResult StepMotionPlanner::project(const Segment& segment, double s,
                                         const Eigen::VectorXd& q_prev,
                                         const MotionSample* previous, bool retry,
                                         const Secant* secant) {
  interpolate_configuration(scene_.system, *segment.q_start, *segment.q_ref_end, s, q_ref_);
  request_.contacts.resize(size_t(held_));
  if (segment.link) {
    const LinkPath& path = *segment.link;
    ContactTask& task = request_.contacts.emplace_back(path.task);
    task.placement = path.placement_at(s);                        // E10-E13
    task.standoff = path.h_from + s * (path.h_to - path.h_from);  // E9 offset along s2's normal
  }
  return project_reference(q_ref_, q_prev, previous, retry, secant);
}

void StepMotionPlanner::guess_forces(const MotionSample* previous, const Secant* secant) {
  for (int t = 0; t < held_; ++t) request_.contacts[size_t(t)].force_guess_W.clear();
  if (!previous) return;
  // Warm start: the previous sample's forces (held contacts only carry force).
  for (const VertexForce& f : previous->forces) {
    ContactTask& task = request_.contacts[size_t(f.contact)];
    if (task.force_guess_W.empty())
      task.force_guess_W.assign(scene_.surfaces.get(task.contact.s1).vertices_S.size(),
                                Eigen::Vector3d::Zero());
    task.force_guess_W[size_t(f.vertex)] = f.force_W;
  }
  if (!secant || !secant->before || secant->before->forces.size() != previous->forces.size())
    return;
  for (size_t i = 0; i < previous->forces.size(); ++i) {
    const VertexForce& f = previous->forces[i];
    const VertexForce& g = secant->before->forces[i];
    if (f.contact == g.contact && f.vertex == g.vertex)
      request_.contacts[size_t(f.contact)].force_guess_W[size_t(f.vertex)] +=
          secant->k * (f.force_W - g.force_W);
  }
}

PostureResult StepMotionPlanner::project_reference(const Eigen::VectorXd& q_ref,
                                                   const Eigen::VectorXd& q_prev,
                                                   const MotionSample* previous, bool retry,
                                                   const Secant* secant) {
  guess_forces(previous, secant);
  if (secant)  // past q_prev on the line from q_before (roots by slerp: a unit quaternion)
    interpolate_configuration(scene_.system, *secant->q_before, q_prev, 1.0 + secant->k,
                              request_.q_init);
  else
    request_.q_init = q_prev;
  request_.q_ref = q_ref;  // E22: the interpolated configuration
  ++solves_;
  PostureResult r = solver_.solve(request_);
  iterations_ += r.iterations;
  if (r.status == PostureStatus::Solved || !retry) return r;
  ++solves_;
  r = retry_solver_.solve(request_);
  iterations_ += r.iterations;
  return r;
}

bool StepMotionPlanner::detour(const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                               std::vector<MotionSample>* samples, size_t first,
                               StepMotion* motion) {
  const std::vector<MotionSample> chain(samples->begin() + long(first), samples->end());
  std::vector<Contact> held;
  for (int t = 0; t < held_; ++t) held.push_back(request_.contacts[size_t(t)].contact);
  const StanceProjector project = [&](const MotionSample& from, const Eigen::VectorXd& q_ref,
                                      MotionSample* out) {
    request_.contacts.resize(size_t(held_));  // the moving link free (E20 keeps it clear)
    PostureResult r =
        project_reference(q_ref, from.q, from.forces.empty() ? nullptr : &from, false);
    if (r.status != PostureStatus::Solved) return false;
    *out = {std::move(r.q), std::move(r.forces), std::move(r.torques)};
    return true;
  };
  StanceRrtResult found = StanceRrt(scene_, *spacing_, held, options_.joint_spacing,
                                    options_.point_spacing, options_.detour)
                              .plan(q_from, chain, q_to, project);
  if (!found.found) {
    motion->message += "; detour: " + found.message;
    return false;
  }
  samples->resize(first);
  samples->insert(samples->end(), std::make_move_iterator(found.path.begin()),
                  std::make_move_iterator(found.path.end()));
  motion->status = MotionStatus::Solved;
  motion->message.clear();
  return true;
}

std::string StepMotionPlanner::describe(const SpacingMeasure& m) const {
  if (m.joint / options_.joint_spacing >= m.point / options_.point_spacing)
    return fixed3(m.joint) + " rad (" + spacing_->joint_name(m) + ")";
  return fixed3(m.point) + " m (" + spacing_->surface_name(m) + ")";
}

bool StepMotionPlanner::run_segment(const Segment& segment, std::vector<MotionSample>* samples,
                                    StepMotion* motion) {
  if (bridge_depth_ == 0) segment_solves_ = solves_;  // each segment (not bridge) has a budget
  const double joint = options_.joint_spacing, point = options_.point_spacing;
  double guess = spacing_->measure(*segment.q_start, *segment.q_ref_end).ratio(joint, point);
  if (segment.link) guess = std::max(guess, segment.link->length() / point);
  const double ds_max = 1.0 / std::max(1.0, std::ceil(guess / kFirstStepFraction));
  double s = 0.0, ds = ds_max;
  int halvings = 0;
  double far_ratio = 0.0;  // the last landing too far at this s (0: none since the last sample)
  // A bridge from q_prev failed: another from it would fail likewise (measured, the climb's step
  // 2: the bridges from the sample before the jump failed whatever their end, those from the next
  // one joined), so the step is halved without one until the next sample.
  bool bridge_failed = false;
  const size_t first = samples->size();
  Eigen::VectorXd q_prev = *segment.q_start;
  // The sample before q_prev and its s, for the secant predictor: measured on the climb's motion
  // (1354 -> 1022 projections, 4800 -> 3908 iterations, step 2 126 -> 97 iterations).
  Eigen::VectorXd q_before;
  double s_before = -1.0;  // < 0: none yet (the segment's start, or the end of a bridge)
  while (true) {
    if (solves_ - segment_solves_ >= options_.max_solves) {
      motion->status = MotionStatus::ProjectionFailed;
      motion->message = std::string(segment.name) + " at s = " + fixed3(s) + ": more than " +
                        std::to_string(options_.max_solves) + " projections";
      return false;
    }
    const double s_next = std::min(1.0, s + ds);
    std::string why;
    MotionStatus failure = MotionStatus::SpacingNotReached;
    if (segment.end && s_next >= 1.0) {  // join the fixed end
      const SpacingMeasure m = spacing_->measure(q_prev, *segment.end);
      if (m.ratio(joint, point) <= 1.0) return true;
      if (halvings >= kHalvingsBeforeBridge &&
          bridge(segment, s, 1.0, q_prev, *segment.end, samples, motion))
        return true;
      why = "the last sample is " + describe(m) + " from the end";
    } else {
      const MotionSample* previous = samples->size() > first ? &samples->back() : nullptr;
      const bool predicts = s_before >= 0.0;
      const Secant secant{&q_before,
                          predicts && samples->size() >= first + 2 ? previous - 1 : nullptr,
                          predicts ? (s_next - s) / (s - s_before) : 0.0};
      // The retry only once halving failed twice: most failures are a step too long, and a retry
      // (the plan's weights) follows the reference less closely (measured: retrying every failure
      // lost a step of the walk).
      PostureResult r = project(segment, s_next, q_prev, previous,
                                halvings >= kHalvingsBeforeBridge, predicts ? &secant : nullptr);
      const SpacingMeasure m =
          r.status == PostureStatus::Solved ? spacing_->measure(q_prev, r.q) : SpacingMeasure{};
      const double ratio = m.ratio(joint, point);
      if (r.status == PostureStatus::Solved && ratio <= 1.0) {
        q_before = q_prev;
        s_before = s;
        q_prev = r.q;
        samples->push_back({std::move(r.q), std::move(r.forces), std::move(r.torques)});
        if (int(samples->size()) > options_.max_samples) {
          motion->status = MotionStatus::SpacingNotReached;
          motion->message = "more than " + std::to_string(options_.max_samples) + " samples";
          return false;
        }
        s = s_next;
        halvings = 0;
        far_ratio = 0.0;
        bridge_failed = false;
        // The next step aims at kFirstStepFraction of the spacing again, scaled by what this one
        // measured (the spacing is about linear in a short step), at most doubled: doubling
        // after every success overshot, and 37 % of the pen's projections (27 of 72 a step)
        // landed too far and were thrown away (with this: 633 -> 399 projections, 382 -> 367
        // samples, at 0.8).
        ds = std::min(ds_max, ds * std::min(2.0, kFirstStepFraction / std::max(ratio, 1e-3)));
        if (!segment.end && s >= 1.0) return true;
        continue;
      }
      const bool jumped = halvings >= 1 && far_ratio > 0.0 && ratio > kJumpRatio * far_ratio;
      if (r.status == PostureStatus::Solved) far_ratio = ratio;
      if (r.status == PostureStatus::Solved && (halvings >= kHalvingsBeforeBridge || jumped) &&
          !bridge_failed &&
          !(bridge_failed = !bridge(segment, s, s_next, q_prev, r.q, samples, motion))) {
        q_prev = r.q;
        s_before = -1.0;  // the bridge's samples lie between: no secant across them
        samples->push_back({std::move(r.q), std::move(r.forces), std::move(r.torques)});
        s = s_next;
        halvings = 0;
        far_ratio = 0.0;
        if (!segment.end && s >= 1.0) return true;
        continue;
      }
      if (r.status == PostureStatus::Solved) {
        why = "a projected sample lands " + describe(m) + " from its predecessor";
      } else {
        failure = MotionStatus::ProjectionFailed;
        why = "no posture (" + r.message + ")";
      }
    }
    // A step halved below ds_max / 2^max_halvings fails too, even when the halvings came in
    // turns with successes: samples creeping ever closer to a point they never pass (an obstacle
    // across the reference, a jump of the projection there) would spend the whole budget.
    if (++halvings > options_.max_halvings || ds < std::ldexp(ds_max, -options_.max_halvings)) {
      motion->status = failure;
      motion->message = std::string(segment.name) + " at s = " + fixed3(s_next) + ": " + why;
      return false;
    }
    ds *= 0.5;  // bisection: a sample halfway to the one that failed
  }
}

bool StepMotionPlanner::bridge(const Segment& segment, double s0, double s1,
                               const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                               std::vector<MotionSample>* samples, StepMotion* motion) {
  if (bridge_depth_ >= kMaxBridgeDepth) return false;
  Segment part{"bridge", &q_from, &q_to, &q_to, std::nullopt};
  if (segment.link) part.link = segment.link->part(s0, s1);
  const size_t before = samples->size();
  ++bridge_depth_;
  const bool joined = run_segment(part, samples, motion);
  --bridge_depth_;
  if (joined) return true;
  samples->resize(before);  // the caller halves its step, as without a bridge
  motion->status = MotionStatus::Solved;
  motion->message.clear();
  return false;
}

void StepMotionPlanner::plan_segments(const PlanStep& a, const PlanStep& b, StepMotion* motion) {
  bool lifts = a.action == "remove" && a.changed && options_.clearance > 0.0;
  bool lands = b.action == "add" && b.changed && options_.clearance > 0.0;
  std::vector<MotionSample>& samples = motion->samples;
  // A link whose placement pins it (a thigh between a seat and the sole of its leg: the knee and
  // ankle cannot move it along the seat's normal with its placement held) cannot leave or approach
  // along the normal: it leaves free instead (E20 keeps it at the collision margin), and the
  // reason is kept for the message should the free travel fail as well.
  std::string normal_failure;
  const auto along_normal = [&](const char* name, const PlanStep& step,
                                std::vector<MotionSample>* out) {
    if (run_segment({name, &step.q, &step.q, nullptr, lift_path(*step.changed, step.q)}, out,
                    motion))
      return true;
    normal_failure += std::string(normal_failure.empty() ? "" : "; ") + motion->message;
    out->clear();
    motion->status = MotionStatus::Solved;
    motion->message.clear();
    return false;
  };
  if (lifts) lifts = along_normal("lift", a, &samples);
  std::vector<MotionSample> landing;  // computed from b upwards, appended backwards
  if (lands) lands = along_normal("approach", b, &landing);
  // A contact made without the approach along the normal is met by the free link itself: its
  // pinned chain may bring it down tangentially (a thigh lowered onto a seat, its sole held on the
  // floor: within 1 cm of its placement the knee end can rise about 2 mm), so E20 holds that one
  // pair at d >= 0 instead of the margin (PostureRequest::approaching); the other pairs keep it.
  if (b.action == "add" && b.changed && !lands) request_.approaching = {*b.changed};
  const Eigen::VectorXd q_from = samples.empty() ? a.q : samples.back().q;
  const Eigen::VectorXd q_to = landing.empty() ? b.q : landing.back().q;
  // A surface lifted from s2 and put down on s2 again (a foot step) glides at the clearance from
  // above its old placement to above its new one; otherwise, or when the glide fails, it is free.
  std::optional<LinkPath> glide;
  if (lifts && lands && a.changed->same_surfaces(*b.changed)) {
    glide = lift_path(*b.changed, b.q);
    glide->from = *lift_task(*a.changed, a.q).placement;
    glide->h_from = options_.clearance;
  }
  const size_t before = samples.size();
  bool travelled = false;
  if (glide) {
    travelled = run_segment({"travel", &q_from, &q_to, &q_to, glide}, &samples, motion);
    if (!travelled) {  // free travel from the same start
      samples.resize(before);
      motion->status = MotionStatus::Solved;
      motion->message.clear();
    }
  }
  if (!travelled &&
      !run_segment({"travel", &q_from, &q_to, &q_to, std::nullopt}, &samples, motion) &&
      !detour(q_from, q_to, &samples, before, motion)) {
    if (!normal_failure.empty())
      motion->message += " (and along the normal: " + normal_failure + ")";
    return;
  }
  samples.insert(samples.end(), std::make_move_iterator(landing.rbegin()),
                 std::make_move_iterator(landing.rend()));
}

StepMotionResult StepMotionPlanner::plan(const PlanStep& a, const PlanStep& b) {
  const auto start = std::chrono::steady_clock::now();
  StepMotionResult out;
  solves_ = 0;
  iterations_ = 0;
  if (set_up(a, b, &out.motion)) plan_segments(a, b, &out.motion);
  out.solves = solves_;
  out.iterations = iterations_;
  out.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace stanceplan
