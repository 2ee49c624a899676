#pragma once
// Starting forces for a program warm started from a configuration alone: at the configuration
// q_init held fixed, the forces the program itself would choose — the least force and torque cost
// (E23-E24) among the forces that balance every floating body (E16-E17) — kept strictly inside
// the cones by a logarithmic barrier:
//   min_lambda  w2 |lambda|^2 + w3 sum_r |tau_r(q_init, lambda)|^2 - mu sum_i e_i log lambda_i
//   s.t.        E16-E17 at q_init (linear in lambda),
// with e_i the even share of coefficient i (the barrier's scale per coefficient) and mu a small
// fraction (`barrier`) of the mean force-cost gradient at the even shares; bilateral force
// components take no barrier. Newton's method with the equality constraints (a convex program:
// tau is linear in lambda at fixed q), from the even shares, steps kept inside lambda > 0.
//
// Why: from even shares the program starts far from balanced (the scaled equilibrium residual
// 0.65 for the humanoid with hands on a wall) and its first Newton steps move the configuration
// far away and back; with these forces a configuration-only warm start takes the iterations of
// one that carries the nearby solution's forces (bench/solver_bench).
#include <Eigen/Dense>

#include "planner/solver/nlp_state.h"

namespace stanceplan {

struct ForceBalanceResult {
  bool balanced = false;  // every equilibrium row met to `tolerance`
  int iterations = 0;     // Newton steps
  double residual = 0.0;  // worst scaled equilibrium row at the end
  double mu = 0.0;        // the barrier weight used
};

// x: the program's starting point with the even shares as its force coefficients (the state at
// x). Newton's method stops when the rows are met to `tolerance` and its step is below 1e-6 of
// the largest coefficient. Replaces the coefficients by the balanced ones when every equilibrium
// row is met to 1e-6 (or `tolerance`, if looser); leaves x as it was otherwise (e.g. when no
// forces at these contact points can hold a body). The state is left at x.
ForceBalanceResult balance_starting_forces(NlpState& state, Eigen::Ref<Eigen::VectorXd> x,
                                           double barrier = 0.01, double tolerance = 1e-9,
                                           int max_iterations = 50);

}  // namespace stanceplan
