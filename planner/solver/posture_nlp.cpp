#include "planner/solver/posture_nlp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "planner/solver/blocks/blocks.h"
#include "planner/solver/torque_hessian.h"

namespace stanceplan {

PostureNlp::PostureNlp(const Scene& scene, const PostureRequest& request,
                       const SolverOptions& options, std::vector<int> active_pairs,
                       std::vector<double> pair_bounds, HessianCache* hessian_cache,
                       const std::vector<std::vector<int>>* torque_dofs,
                       const std::vector<std::vector<int>>* polygon_rows)
    : layout_(scene, request, options),
      state_(scene, request, options, layout_),
      objective_(state_) {
  const System& system = scene.system;
  auto add = [&](std::unique_ptr<ConstraintBlock> block) {
    if (block->rows() > 0) blocks_.push_back(std::move(block));
  };
  add(std::make_unique<QuaternionNormBlock>(system));
  for (int t = 0; t < static_cast<int>(request.contacts.size()); ++t) {
    add(std::make_unique<ContactGeometryBlock>(state_, t));
    if (!request.contacts[t].placement)
      add(std::make_unique<PolygonBlock>(state_, t,
                                         polygon_rows ? &(*polygon_rows)[size_t(t)] : nullptr));
  }
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.floating() && entity.model->total_mass > 0.0)
      add(std::make_unique<EquilibriumBlock>(state_, e));
    if (options.enforce_torque_limits && entity.kind != EntityKind::Object &&
        entity.model->num_dofs() > 0)
      add(std::make_unique<TorqueLimitBlock>(state_, e,
                                             torque_dofs ? &(*torque_dofs)[size_t(e)] : nullptr));
  }
  if (pair_bounds.size() != active_pairs.size())
    pair_bounds.assign(active_pairs.size(), options.collision_margin);
  if (scene.collision && options.enforce_collisions && !active_pairs.empty())
    add(std::make_unique<CollisionBlock>(state_, std::move(active_pairs), std::move(pair_bounds)));
  std::vector<int> columns;
  for (const auto& block : blocks_) {
    first_row_.push_back(m_);
    for (int r = 0; r < block->rows(); ++r) {
      columns.clear();
      block->row_columns(r, &columns);
      sort_unique(&columns);
      for (int c : columns) {
        rows_.push_back(m_ + r);
        cols_.push_back(c);
      }
    }
    m_ += block->rows();
  }
  J_.setZero(m_, layout_.n);
  H_.setZero(layout_.n, layout_.n);
  grad_.setZero(layout_.n);
  grad_step_.setZero(layout_.n);
  x_step_.setZero(layout_.n);
  x0_ = make_starting_point(state_);
  if (torque_dofs) torque_dofs_ = *torque_dofs;
  if (polygon_rows) polygon_rows_ = *polygon_rows;
  if (options.hessian == HessianMode::LimitedMemory) return;
  const HessianCache::Key key = hessian_key();
  if (hessian_cache) hessian_ = hessian_cache->find(key);
  if (hessian_) return;
  hessian_ = options.hessian == HessianMode::Analytic ? measure_analytic_structure()
                                                      : measure_hessian_structure();
  if (hessian_cache) hessian_cache->insert(key, hessian_);
}

// Everything the Hessian's structure depends on: the variables, the contacts and how each enters
// the program, the non-collision rows and their columns, and the objective's torque term.
HessianCache::Key PostureNlp::hessian_key() const {
  HessianCache::Key key = {int(state_.options.hessian), n(), layout_.nq,
                           state_.options.w_torque > 0.0 ? 1 : 0};
  for (const ContactTask& task : state_.request.contacts) {
    const Contact& c = task.contact;
    key.insert(key.end(),
               {c.s1.entity, c.s1.index, c.s2.entity, c.s2.index, c.bilateral ? 1 : 0,
                task.loaded ? 1 : 0, task.placement ? 1 : 0, task.placement_target ? 1 : 0});
  }
  int smooth_rows = m_;  // the collision block, when there is one, comes last
  if (!blocks_.empty() && blocks_.back()->family() == "collision") smooth_rows = first_row_.back();
  key.push_back(smooth_rows);
  // Which rows, not only how many (separators -1 and -2 keep the two lists apart).
  for (int list = 0; list < 2; ++list)
    for (const std::vector<int>& rows : list == 0 ? torque_dofs_ : polygon_rows_) {
      key.push_back(-1 - list);
      key.insert(key.end(), rows.begin(), rows.end());
    }
  for (size_t k = 0; k < rows_.size() && rows_[k] < smooth_rows; ++k) {
    key.push_back(rows_[k]);
    key.push_back(cols_[k]);
  }
  return key;
}

void PostureNlp::variable_bounds(double* lower, double* upper) const {
  constexpr double kInf = 1e19;
  std::fill(lower, lower + n(), -kInf);
  std::fill(upper, upper + n(), kInf);
  const System& system = state_.scene.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    const Model& model = *entity.model;
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& joint = model.joints[model.dof_joints[k]];
      if (!joint.has_position_limits) continue;
      const int i = system.offset(e) + entity.first_dof() + k;
      lower[i] = joint.lower;  // E6
      upper[i] = joint.upper;
    }
  }
  for (const ForceBlock& block : layout_.forces)
    if (!block.bilateral)
      std::fill(lower + block.first_column, lower + block.first_column + block.size(), 0.0);  // E7
}

void PostureNlp::constraint_bounds(double* lower, double* upper) const {
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const int rows = blocks_[b]->rows();
    blocks_[b]->bounds(Eigen::Map<Eigen::VectorXd>(lower + first_row_[b], rows),
                       Eigen::Map<Eigen::VectorXd>(upper + first_row_[b], rows));
  }
}

void PostureNlp::structure(int* rows, int* cols) const {
  std::copy(rows_.begin(), rows_.end(), rows);
  std::copy(cols_.begin(), cols_.end(), cols);
}

void PostureNlp::starting_point(double* x) const {
  std::copy(x0_.data(), x0_.data() + n(), x);
}

namespace {

// Coefficients of the K generators (E5) that sum to the world force f, clamped inside the cone:
// with generators equally spaced around s2's normal z2 at angles 2 pi k / K from x2,
//   lambda_k = (f.z2) / (K c) + 2 (f_t . e_k) / (K mu c),   c = cos(atan(mu)),
// sums to f exactly when f is inside the linearised cone. Bilateral: the world components.
Eigen::VectorXd cone_coefficients(const ForceBlock& block, const ContactFrames& frames, double mu,
                                  const Eigen::Vector3d& f) {
  if (block.bilateral) return f;
  const int K = block.per_vertex;
  const double c = 1.0 / std::sqrt(1.0 + mu * mu);
  const double normal = f.dot(frames.z2), tx = f.dot(frames.x2), ty = f.dot(frames.y2);
  Eigen::VectorXd lambda(K);
  for (int k = 0; k < K; ++k) {
    const double angle = 2.0 * M_PI * k / K;
    const double tangential = tx * std::cos(angle) + ty * std::sin(angle);
    const double turn = mu > 0.0 ? 2.0 * tangential / (K * mu * c) : 0.0;
    lambda[k] = std::max(normal / (K * c) + turn, 1e-3);
  }
  return lambda;
}

}  // namespace

// The request's configuration and, for every loaded contact, its force guess (the parent node's
// forces, or the balanced forces PostureSolver computes at q_init: force_balance.h) or else an
// even share of the weight of every floating body over the loaded vertices, as an interior point
// (lambda > 0) of the cone coefficients. (The least change of the even shares that balances the
// bodies took more iterations, 6/14/12 instead of 7/11/10 for 2/3/4 contacts in session 4's
// bench/solver_bench: Ipopt's first steps then grow the forces far from there; the least-cost
// balance of force_balance.h does not.)
Eigen::VectorXd make_starting_point(NlpState& state) {
  const PostureRequest& request = state.request;
  const NlpLayout& layout = state.layout;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(layout.n);
  x0.head(layout.nq) = request.q_init;
  double weight = 0.0;
  for (const Entity& e : state.scene.system.entities())
    if (e.floating()) weight += e.model->total_mass * state.scene.gravity.norm();
  int vertices = 0;
  for (const ForceBlock& block : layout.forces) vertices += block.num_vertices;
  const double per_vertex = vertices > 0 ? weight / vertices : 0.0;
  const double mu = state.options.friction;
  const double cos_half = 1.0 / std::sqrt(1.0 + mu * mu);
  state.set_x(x0.data());  // the generators' world directions at q_init
  for (const ForceBlock& block : layout.forces) {
    auto lambda = x0.segment(block.first_column, block.size());
    const std::vector<Eigen::Vector3d>& guess = request.contacts[size_t(block.task)].force_guess_W;
    if (int(guess.size()) == block.num_vertices) {
      for (int j = 0; j < block.num_vertices; ++j)
        lambda.segment(j * block.per_vertex, block.per_vertex) =
            cone_coefficients(block, state.frames[size_t(block.task)], mu, guess[size_t(j)]);
    } else if (block.bilateral) {
      lambda.setZero();
    } else {
      lambda.setConstant(std::max(per_vertex / (block.per_vertex * cos_half), 1e-3));
    }
  }
  state.set_x(x0.data());
  return x0;
}

void PostureNlp::update(const double* x, bool new_x) {
  if (new_x || !has_x_) state_.set_x(x);
  has_x_ = true;
}

double PostureNlp::objective(const double* x, bool new_x) {
  update(x, new_x);
  return objective_.value(state_);
}

void PostureNlp::objective_gradient(const double* x, bool new_x, double* grad) {
  update(x, new_x);
  objective_.gradient(state_, Eigen::Map<Eigen::VectorXd>(grad, n()));
}

void PostureNlp::constraints(const double* x, bool new_x, double* g) {
  update(x, new_x);
  for (size_t b = 0; b < blocks_.size(); ++b)
    blocks_[b]->evaluate(state_,
                         Eigen::Map<Eigen::VectorXd>(g + first_row_[b], blocks_[b]->rows()));
}

const Eigen::MatrixXd& PostureNlp::dense_jacobian(const double* x, bool new_x) {
  update(x, new_x);
  J_.setZero();
  for (size_t b = 0; b < blocks_.size(); ++b)
    blocks_[b]->jacobian(state_, J_.middleRows(first_row_[b], blocks_[b]->rows()));
  return J_;
}

void PostureNlp::jacobian_values(const double* x, bool new_x, double* values) {
  dense_jacobian(x, new_x);
  for (size_t k = 0; k < rows_.size(); ++k) values[k] = J_(rows_[k], cols_[k]);
}

}  // namespace stanceplan

namespace stanceplan {

void PostureNlp::hessian_structure(int* rows, int* cols) const {
  std::copy(hessian_->rows.begin(), hessian_->rows.end(), rows);
  std::copy(hessian_->cols.begin(), hessian_->cols.end(), cols);
}

void PostureNlp::lagrangian_gradient(double obj_factor, const Eigen::Ref<const Eigen::VectorXd>& y,
                                     Eigen::Ref<Eigen::VectorXd> out) {
  lagrangian_gradient(state_, obj_factor, y, out);
}

void PostureNlp::lagrangian_gradient(NlpState& state, double obj_factor,
                                     const Eigen::Ref<const Eigen::VectorXd>& y,
                                     Eigen::Ref<Eigen::VectorXd> out) {
  // Signed distance is only piecewise smooth (its witness features jump, e.g. between parallel
  // faces): differencing its gradient gives meaningless curvature, so collision rows are given
  // none, as in Gauss-Newton. Every other family is smooth.
  J_.setZero();
  for (size_t b = 0; b < blocks_.size(); ++b)
    if (blocks_[b]->family() != "collision")
      blocks_[b]->jacobian(state, J_.middleRows(first_row_[b], blocks_[b]->rows()));
  objective_.gradient(state, out);
  out *= obj_factor;
  out.noalias() += J_.transpose() * y;
}

namespace {

// A deterministic pseudo-random number in [0, 1) for index i of stream `seed` (splitmix64): the
// same on every platform, and without the regularity (i % 5 patterns) that once made a symmetric
// probe hide a dependence.
double generic_value(int i, int seed) {
  uint64_t z = (uint64_t(uint32_t(seed)) << 32 | uint32_t(i)) + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace

// A generic point: every joint off its neutral value by a different amount (inside its limits),
// every force coefficient and multiplier nonzero, so that no dependence hides behind a zero factor.
void PostureNlp::probe_point(int seed, Eigen::VectorXd* x, Eigen::VectorXd* y) const {
  std::vector<double> lower(static_cast<size_t>(n())), upper(static_cast<size_t>(n()));
  variable_bounds(lower.data(), upper.data());
  const int nq = layout_.nq;
  x->resize(n());
  x->head(nq) = state_.scene.system.neutral_configuration();
  for (int k = 0; k < nq; ++k) {
    const double moved = (*x)[k] + 0.03 + 0.05 * generic_value(k, seed);
    const double room = 0.1 * (upper[size_t(k)] - lower[size_t(k)]);
    (*x)[k] = std::clamp(moved, lower[size_t(k)] + room, upper[size_t(k)] - room);
  }
  for (int i = nq; i < n(); ++i) (*x)[i] = 0.5 + generic_value(i, seed);
  y->resize(m_);
  for (int r = 0; r < m_; ++r)
    (*y)[r] = (r % 2 ? -1.0 : 1.0) * (0.5 + generic_value(n() + r, seed));
}

// The request with its values replaced by generic ones (same contacts, same shape): the structure
// then depends on the shape alone, so that HessianCache returns what measuring would (a placement
// angle of exactly 0 would hide a dependence and make the cached structure depend on which request
// came first).
PostureRequest PostureNlp::generic_request(const Eigen::VectorXd& q, int seed) const {
  PostureRequest generic = state_.request;
  generic.q_init = q;
  generic.q_ref = q;
  for (int k = 0; k < q.size(); ++k)
    generic.q_ref[k] += 0.003 * (1.0 + generic_value(k, seed + 100));
  for (ContactTask& task : generic.contacts) {
    if (task.placement) *task.placement = {0.011, -0.013, 0.017};
    if (task.placement_target) *task.placement_target = {0.019, 0.007, -0.023};
  }
  return generic;
}

// The analytic Hessian's structure: the entries nonzero at either of two generic points (an
// entry that can be nonzero is exactly zero at a generic point only by coincidence).
std::shared_ptr<const HessianStructure> PostureNlp::measure_analytic_structure() {
  const int nq = layout_.nq;
  std::vector<char> seen(size_t(n()) * size_t(n()), 0);
  for (int seed : {1, 2}) {
    Eigen::VectorXd x, y;
    probe_point(seed, &x, &y);
    const PostureRequest request = generic_request(x.head(nq), seed);
    NlpState state(state_.scene, request, state_.options, layout_);
    state.set_x(x.data());
    analytic_hessian(state, 1.0, y, H_);
    for (int j = 0; j < n(); ++j)
      for (int i = j; i < n(); ++i)
        if (H_(i, j) != 0.0) seen[size_t(i) * size_t(n()) + size_t(j)] = 1;
  }
  auto structure = std::make_shared<HessianStructure>();
  for (int i = 0; i < n(); ++i)
    for (int j = 0; j <= i; ++j)
      if (seen[size_t(i) * size_t(n()) + size_t(j)]) {
        structure->rows.push_back(i);
        structure->cols.push_back(j);
        structure->sources.push_back(HessianStructure::Source::Exact);
      }
  return structure;
}

std::shared_ptr<const HessianStructure> PostureNlp::measure_hessian_structure() {
  const int nq = layout_.nq, nl = n() - nq;
  Eigen::VectorXd x, y;
  probe_point(1, &x, &y);
  const PostureRequest request = generic_request(x.head(nq), 1);
  NlpState state(state_.scene, request, state_.options, layout_);
  state.set_x(x.data());
  lagrangian_gradient(state, 1.0, y, grad_);
  std::vector<char> pattern(size_t(n()) * size_t(nq), 0);
  for (int k = 0; k < nq; ++k) {
    x_step_ = x;
    x_step_[k] += 1e-3;
    state.set_x(x_step_.data());
    lagrangian_gradient(state, 1.0, y, grad_step_);
    for (int i = 0; i < n(); ++i)
      pattern[size_t(k) * size_t(n()) + size_t(i)] = grad_step_[i] != grad_[i];
  }
  auto structure = std::make_shared<HessianStructure>();
  structure->groups = make_hessian_groups(std::move(pattern), n(), nq);
  // lambda-lambda: 2 w_force I + 2 w_torque (dtau/dlambda)^T (dtau/dlambda) (see hessian_values).
  std::vector<char> forces(size_t(nl) * size_t(nl), 0);
  for (int a = 0; a < nl; ++a) forces[size_t(a) * size_t(nl) + size_t(a)] = 1;
  if (state.options.w_torque > 0.0 && nl > 0) {
    state.set_x(x.data());
    state.ensure_torques();
    for (const Eigen::MatrixXd& D : state.dtau_dx)
      for (int r = 0; r < D.rows(); ++r)
        for (int a = 0; a < nl; ++a)
          if (D(r, nq + a) != 0.0)
            for (int b = 0; b < nl; ++b)
              if (D(r, nq + b) != 0.0) forces[size_t(a) * size_t(nl) + size_t(b)] = 1;
  }
  using Source = HessianStructure::Source;
  const HessianGroups& groups = structure->groups;
  for (int i = 0; i < n(); ++i)
    for (int j = 0; j <= i; ++j) {
      Source source = Source::Exact;
      if (j < nq) {
        if (!groups.needed(i, j)) continue;
        // From column j, or in the q-q block from column i, or the mean of both when both read
        // it; make_hessian_groups guarantees one side.
        const bool ij = groups.readable(i, j);
        const bool ji = i < nq && groups.readable(j, i);
        source = ij && ji ? Source::Mean : ij ? Source::Column : Source::Mirror;
      } else if (!forces[size_t(i - nq) * size_t(nl) + size_t(j - nq)]) {
        continue;
      }
      structure->rows.push_back(i);
      structure->cols.push_back(j);
      structure->sources.push_back(source);
    }
  return structure;
}

void PostureNlp::hessian_values(const double* x, bool new_x, double obj_factor, const double* y_in,
                                double* values) {
  if (state_.options.hessian == HessianMode::Analytic) {
    analytic_hessian_values(x, new_x, obj_factor, y_in, values);
    return;
  }
  update(x, new_x);
  const Eigen::Map<const Eigen::VectorXd> y(y_in, m_);
  const int nq = layout_.nq;
  lagrangian_gradient(obj_factor, y, grad_);
  // Forward differences of the exact gradient along the configuration directions give the q-q
  // block and the lambda-q block (columns k < nq), several columns per evaluation where they move
  // different rows (hessian_groups.h).
  auto step = [x](int k) { return 1e-7 * std::max(1.0, std::abs(x[k])); };
  x_step_ = Eigen::Map<const Eigen::VectorXd>(x, n());
  for (const std::vector<int>& group : hessian_->groups.groups) {
    for (int k : group) x_step_[k] += step(k);
    state_.set_x(x_step_.data());
    lagrangian_gradient(obj_factor, y, grad_step_);
    for (int k : group) {
      H_.col(k) = (grad_step_ - grad_) / step(k);
      x_step_[k] = x[k];
    }
  }
  state_.set_x(x);  // later calls with new_x = false expect the state at x
  // lambda-lambda: the constraints are linear in lambda; the objective contributes
  // 2 w_force I + 2 w_torque (dtau/dlambda)^T (dtau/dlambda).
  const SolverOptions& o = state_.options;
  const int nl = n() - nq;
  if (nl > 0) {
    auto Hll = H_.bottomRightCorner(nl, nl);
    Hll.setZero();
    Hll.diagonal().array() += obj_factor * 2.0 * o.w_force;
    if (o.w_torque > 0.0) {
      state_.ensure_torques();
      for (const Eigen::MatrixXd& D : state_.dtau_dx)
        if (D.size() > 0)
          Hll.noalias() +=
              obj_factor * 2.0 * o.w_torque * D.rightCols(nl).transpose() * D.rightCols(nl);
    }
  }
  using Source = HessianStructure::Source;
  for (size_t k = 0; k < hessian_->rows.size(); ++k) {
    const int i = hessian_->rows[k], j = hessian_->cols[k];
    switch (hessian_->sources[k]) {
      case Source::Column:
      case Source::Exact:
        values[k] = H_(i, j);
        break;
      case Source::Mirror:
        values[k] = H_(j, i);
        break;
      case Source::Mean:
        values[k] = 0.5 * (H_(i, j) + H_(j, i));
        break;
    }
  }
}

// Every block adds its rows' curvature weighted by its multipliers; the torque rows and the
// objective's torque term leave weights for one pass over the loads (torque_hessian.h).
void PostureNlp::analytic_hessian(NlpState& state, double obj_factor,
                                  const Eigen::Ref<const Eigen::VectorXd>& y,
                                  Eigen::Ref<Eigen::MatrixXd> H) const {
  H.setZero();
  state.ensure_force_jacobians();
  for (Eigen::VectorXd& w : state.torque_weights) w.setZero();
  objective_.add_hessian(state, obj_factor, H);
  for (size_t b = 0; b < blocks_.size(); ++b)
    blocks_[b]->add_hessian(state, y.segment(first_row_[b], blocks_[b]->rows()), H);
  add_weighted_torque_hessian(state, H);
}

void PostureNlp::analytic_hessian_values(const double* x, bool new_x, double obj_factor,
                                         const double* y, double* values) {
  update(x, new_x);
  analytic_hessian(state_, obj_factor, Eigen::Map<const Eigen::VectorXd>(y, m_), H_);
  for (size_t k = 0; k < hessian_->rows.size(); ++k)
    values[k] = H_(hessian_->rows[k], hessian_->cols[k]);
}

}  // namespace stanceplan
