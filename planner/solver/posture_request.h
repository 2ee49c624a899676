#pragma once
// The input of one inverse-kinematics-and-statics solve (docs/METHOD.md section 4).
//   realise a stance:  every contact loaded;
//   case 1 (add c):    sigma's contacts loaded, c touched but unloaded with a free placement;
//   case 2 (remove c): every contact of sigma touched, c unloaded.
#include <Eigen/Core>
#include <atomic>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/contact/contact.h"
#include "planner/solver/stall_monitor.h"

namespace stanceplan {

struct ContactTask {
  Contact contact;
  bool loaded = true;  // carries force (lambda variables) in this solve
  // Fixed placement (E10-E13). nullopt: free, s1 kept inside s2's polygon (case 1 relaxation).
  std::optional<Placement> placement;
  // Optional E25 target for a free placement (obj4: pull s1's origin towards (x, y) of s2's plane).
  std::optional<Placement> placement_target;
  // E9 with an offset: s1's origin this far above s2's plane, along s2's normal (m). Only for an
  // unloaded contact with a fixed placement: a link held clear of its surface (planner/motion/,
  // leaving or approaching a contact along the normal). 0: touching.
  double standoff = 0.0;
  // Warm start of a loaded contact's forces: the force by s2 on s1 at each vertex of s1 (world
  // frame), e.g. the parent node's. Empty: an even share of the weight (PostureNlp).
  std::vector<Eigen::Vector3d> force_guess_W;
};

struct PostureRequest {
  std::vector<ContactTask> contacts;
  Eigen::VectorXd q_init;  // initial guess (warm start), System::nq()
  Eigen::VectorXd q_ref;   // milestone configuration of the objective (E21); empty: q_init
  // A candidate's solve may be stopped when it makes no progress (StallRule::budget, iterations;
  // 0: the solver's options decide): set by the search for its candidates, never by the motion
  // planner or a single posture, which need every solve to run its course.
  int progress_budget = 0;
  // Contacts about to be made whose s1 is free in this request (a motion's link approaching its
  // surface off the normal: planner/motion/step_motion.h). E20 keeps the pair of s1's link and
  // s2's link at distance >= 0 rather than the margin: the link must come to touch that surface,
  // and a link pinned by its chain (a sole below a thigh held on a seat) meets it tangentially,
  // below the margin centimetres before its placement. Every other pair keeps the margin.
  std::vector<Contact> approaching;
};

// How Ipopt gets second derivatives: its limited-memory (L-BFGS) approximation; the Hessian of the
// Lagrangian from forward differences of the exact analytic gradient along the configuration
// directions (the lambda-lambda block exact: every constraint is linear in lambda); or the exact
// analytic Hessian (second- and third-order kinematics, planner/solver/hessian_terms.h).
enum class HessianMode { LimitedMemory, FiniteDifference, Analytic };

struct SolverOptions {
  double friction = 1.0;    // Coulomb coefficient mu of every unilateral contact
  int cone_generators = 4;  // K: generators of the linearised friction cone (E5)
  // Objective weights (E21-E25): configuration, contact force (lambda), joint torque, placement.
  double w_configuration = 1.0;
  double w_force = 1e-5;
  double w_torque = 1e-5;
  double w_placement = 10.0;
  double collision_margin = 0.005;          // E20: signed distance >= margin (m)
  double collision_active_distance = 0.05;  // pairs closer than this enter the program
  int max_active_set_rounds =
      4;  // re-solves when a pair or torque outside its active set is violated
  // E19 rows enter the program only for joints whose torque at the starting point is at least this
  // fraction of the effort limit (0: every row); a solution that exceeds a limit left out is solved
  // again with it. Far-from-limit rows are dense (every joint above, every load): leaving them out
  // makes the linear algebra cheaper (bench/solver_bench).
  double torque_active_fraction = 0.5;
  // The polygon rows (a vertex of s1 inside an edge of s2) of a loaded contact with a free
  // placement enter only when the vertex is nearer than this to the edge's line at the starting
  // point (m; INFINITY: every row); a solution with a vertex beyond an edge left out is solved
  // again with it. A foot far inside the floor needs none. Case 1's added (unloaded) contact keeps
  // every row.
  double polygon_active_distance = 0.1;
  // Without force guesses, start from the forces that balance the bodies at q_init at least cost
  // (force_balance.h) rather than from even shares of the weight.
  bool balance_starting_forces = true;
  HessianMode hessian = HessianMode::Analytic;
  int max_iterations = 100;
  // A solve whose constraint violation stalls stops before max_iterations (stall_monitor.h):
  // status IterationLimit, message "Stalled (...)". stall.after = 0: every solve gets its budget.
  StallRule stall;
  double tolerance = 1e-6;  // constraint violation (Ipopt constr_viol_tol): every physical residual
  // Complementarity (compl_inf_tol): the products of an inequality's slack and its multiplier, e.g.
  // a cone coefficient (N) times its bound multiplier. 1e-4 instead of 1e-6 ends a warm solve 1-3
  // iterations earlier (bench/solver_bench) and changes no residual above.
  double complementarity_tolerance = 1e-4;
  double optimality_tolerance = 1e-4;  // Ipopt tol / dual_inf_tol (the objective is a regulariser)
  bool derivative_test = false;        // Ipopt's first-order derivative checker (tests only)
  // Families that can be switched off (diagnosis, experiments).
  bool enforce_torque_limits = true;
  bool enforce_collisions = true;
  // When a solve fails, re-solve without torque limits, then without collision avoidance, to name
  // the family that makes the request infeasible (PostureResult::blocking_family). Costs up to
  // two more solves per failure: on for single postures, off in the search.
  bool diagnose_infeasibility = false;
  // When set and true, a solve stops at its next iteration (status NumericalFailure, "cancelled").
  const std::atomic<bool>* cancel = nullptr;
  int print_level = 0;  // Ipopt's console output (0 = silent, 5 = per iteration)
  // Further Ipopt options by name, applied last (values parsed as integer, number or string).
  std::vector<std::pair<std::string, std::string>> ipopt_options;
};

}  // namespace stanceplan
