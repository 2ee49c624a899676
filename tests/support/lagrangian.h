#pragma once
// For the Hessian tests: the gradient of the Lagrangian obj_factor f + y^T g from the program's
// exact first derivatives, and a random point near the program's start with random multipliers.
#include <Eigen/Core>
#include <random>

#include "planner/solver/posture_nlp.h"

namespace stanceplan::test {

// Every family the program has (build it without collision rows: they get no curvature).
inline Eigen::VectorXd lagrangian_gradient(PostureNlp& nlp, const Eigen::VectorXd& x,
                                           double obj_factor, const Eigen::VectorXd& y) {
  Eigen::VectorXd grad(nlp.n());
  nlp.objective_gradient(x.data(), true, grad.data());
  return obj_factor * grad + nlp.dense_jacobian(x.data(), false).transpose() * y;
}

struct LagrangianPoint {
  Eigen::VectorXd x, y;
  double obj_factor = 0.7;
};

// The starting point with every configuration entry moved by up to q_spread (root quaternions
// leave the unit sphere), every force coefficient increased by up to 0.5, multipliers in [-1, 1].
inline LagrangianPoint random_lagrangian_point(const PostureNlp& nlp, unsigned seed,
                                               double q_spread) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = nlp.n(), nq = nlp.layout().nq;
  LagrangianPoint p;
  p.x.resize(n);
  nlp.starting_point(p.x.data());
  for (int i = 0; i < nq; ++i) p.x[i] += q_spread * u(rng);
  for (int i = nq; i < n; ++i) p.x[i] += 0.5 * std::abs(u(rng));
  p.y.resize(nlp.m());
  for (int i = 0; i < nlp.m(); ++i) p.y[i] = u(rng);
  return p;
}

}  // namespace stanceplan::test
