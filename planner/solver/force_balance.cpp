#include "planner/solver/force_balance.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {
namespace {

// The equilibrium rows of every floating body with mass at the state's x: g0 and their Jacobian
// A with respect to the force coefficients (the rows are linear in them).
struct Equilibrium {
  Eigen::VectorXd g0;
  Eigen::MatrixXd A;
};
Equilibrium equilibrium_rows(NlpState& state) {
  const System& system = state.scene.system;
  std::vector<std::unique_ptr<EquilibriumBlock>> blocks;
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).floating() && system.entity(e).model->total_mass > 0.0)
      blocks.push_back(std::make_unique<EquilibriumBlock>(state, e));
  const int rows = 6 * static_cast<int>(blocks.size());
  Equilibrium eq{Eigen::VectorXd(rows), Eigen::MatrixXd::Zero(rows, state.layout.n)};
  for (size_t b = 0; b < blocks.size(); ++b) {
    blocks[b]->evaluate(state, eq.g0.segment(6 * b, 6));
    blocks[b]->jacobian(state, eq.A.middleRows(6 * b, 6));
  }
  eq.A = eq.A.rightCols(state.layout.n - state.layout.nq).eval();
  return eq;
}

}  // namespace

ForceBalanceResult balance_starting_forces(NlpState& state, Eigen::Ref<Eigen::VectorXd> x,
                                           double barrier, double tolerance, int max_iterations) {
  ForceBalanceResult out;
  const NlpLayout& layout = state.layout;
  const SolverOptions& o = state.options;
  const int nq = layout.nq, nl = layout.n - nq;
  if (nl == 0) return out;
  const Equilibrium eq = equilibrium_rows(state);
  if (eq.g0.size() == 0) return out;
  const Eigen::VectorXd even = x.tail(nl);
  std::vector<char> unilateral(size_t(nl), 0);
  for (const ForceBlock& block : layout.forces)
    for (int i = 0; i < block.size(); ++i)
      unilateral[size_t(block.first_column - nq + i)] = !block.bilateral;

  // Force cost F(lambda) = 1/2 lambda^T Q lambda + c^T lambda (+ const): E23 and, with tau
  // linear in lambda at fixed q (tau = tau_x + U (lambda - even)), E24.
  state.ensure_torques();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(nl, nl) * (2.0 * o.w_force);
  Eigen::VectorXd gradient_even = 2.0 * o.w_force * even;  // dF/dlambda at the even shares
  for (size_t e = 0; e < state.tau.size(); ++e) {
    if (state.tau[e].size() == 0) continue;
    const auto U = state.dtau_dx[e].rightCols(nl);
    Q.noalias() += 2.0 * o.w_torque * U.transpose() * U;
    gradient_even.noalias() += 2.0 * o.w_torque * U.transpose() * state.tau[e];
  }
  Q.diagonal().array() += 1e-12 * (1.0 + Q.diagonal().maxCoeff());  // w2 = 0 and bilateral
  double mean_gradient = 0.0;
  int count = 0;
  for (int k = 0; k < nl; ++k)
    if (unilateral[size_t(k)]) mean_gradient += std::abs(gradient_even[k]), ++count;
  const double mu = count > 0 ? barrier * mean_gradient / count : 0.0;
  out.mu = mu;

  Eigen::VectorXd lambda = even, gradient(nl), residual(eq.g0.size()), step(nl);
  Eigen::MatrixXd H(nl, nl);
  auto residual_at = [&](const Eigen::VectorXd& l) { return eq.g0 + eq.A * (l - even); };
  for (; out.iterations < max_iterations; ++out.iterations) {
    gradient = gradient_even + Q * (lambda - even);
    H = Q;
    for (int k = 0; k < nl; ++k)
      if (unilateral[size_t(k)]) {
        gradient[k] -= mu * even[k] / lambda[k];
        H(k, k) += mu * even[k] / (lambda[k] * lambda[k]);
      }
    residual = residual_at(lambda);
    // [H A^T; A 0] [step; nu] = [-gradient; -residual], by the Schur complement of H.
    const Eigen::LLT<Eigen::MatrixXd> llt(H);
    if (llt.info() != Eigen::Success) break;
    const Eigen::MatrixXd HiAt = llt.solve(eq.A.transpose());
    const Eigen::VectorXd Hig = llt.solve(gradient);
    Eigen::MatrixXd S = eq.A * HiAt;
    S.diagonal().array() += 1e-14 * (1.0 + S.diagonal().maxCoeff());
    const Eigen::VectorXd nu = S.ldlt().solve(residual - eq.A * Hig);
    step = -Hig - HiAt * nu;
    double t = 1.0;  // fraction to the boundary: lambda stays > 0
    for (int k = 0; k < nl; ++k)
      if (unilateral[size_t(k)] && step[k] < 0.0) t = std::min(t, -0.99 * lambda[k] / step[k]);
    lambda += t * step;
    if (t == 1.0 && residual_at(lambda).cwiseAbs().maxCoeff() <= tolerance &&
        step.cwiseAbs().maxCoeff() <= 1e-6 * (1.0 + lambda.cwiseAbs().maxCoeff())) {
      ++out.iterations;
      break;
    }
  }
  out.residual = residual_at(lambda).cwiseAbs().maxCoeff();
  out.balanced = std::isfinite(out.residual) && out.residual <= std::max(tolerance, 1e-6);
  if (out.balanced) {
    x.tail(nl) = lambda;
    state.set_x(x.data());
  }
  return out;
}

}  // namespace stanceplan
