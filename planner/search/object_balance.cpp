#include "planner/search/object_balance.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace stanceplan {
namespace {

// The wrench columns of one contact's cone generators on `object`, about its centre of mass c_W:
// [u; (p - c) x u] per vertex p of s1 and generator u, negated when the object is s2's entity (the
// force s2 exerts on s1 is the reaction on s2).
void append_cone_wrenches(const Scene& scene, const std::vector<ModelData>& data,
                          const Contact& contact, int object, const Eigen::Vector3d& c_W,
                          double friction, int cone_generators,
                          std::vector<Eigen::Vector<double, 6>>* out) {
  const Surface& s1 = scene.surfaces.get(contact.s1);
  const Surface& s2 = scene.surfaces.get(contact.s2);
  const Eigen::Isometry3d T_WS2 = data[size_t(contact.s2.entity)].T_WL[size_t(s2.link)] * s2.T_LS;
  const Eigen::Isometry3d T_WL1 = data[size_t(contact.s1.entity)].T_WL[size_t(s1.link)];
  const Eigen::Vector3d z2_W = T_WS2.linear().col(2);
  std::vector<Eigen::Vector3d> points_W;
  if (s1.is_point())  // a sphere touches at c - r z_s2
    points_W.push_back(T_WL1 * s1.center_L() - s1.radius * z2_W);
  else
    for (const Eigen::Vector3d& v_L : s1.vertices_L()) points_W.push_back(T_WL1 * v_L);
  const double sign = contact.s1.entity == object ? 1.0 : -1.0;
  for (int k = 0; k < cone_generators; ++k) {  // E5, as the program builds its cones
    const double angle = 2.0 * M_PI * k / cone_generators;
    const Eigen::Vector3d u_S(friction * std::cos(angle), friction * std::sin(angle), 1.0);
    const Eigen::Vector3d u_W = sign * (T_WS2.linear() * u_S.normalized());
    for (const Eigen::Vector3d& p_W : points_W) {
      Eigen::Vector<double, 6> w;
      w << u_W, (p_W - c_W).cross(u_W);
      out->push_back(w);
    }
  }
}

bool tested_object(const Scene& scene, int e) {
  const Entity& entity = scene.system.entity(e);
  return entity.kind == EntityKind::Object && entity.model->num_dofs() == 0 &&
         entity.model->total_mass > 0.0;
}

// E16-E17 for `object` alone with the cone forces of `kept`: the least wrench residual, relative
// to its weight (torques over its size, the largest distance of a contact point from its centre).
bool object_balances(const Scene& scene, const std::vector<ModelData>& data,
                     const std::vector<Contact>& kept, int object, double friction,
                     int cone_generators, double tolerance) {
  const Model& model = *scene.system.entity(object).model;
  const Eigen::Vector3d c_W = data[size_t(object)].subtree_moment_W[0] / model.total_mass;
  std::vector<Eigen::Vector<double, 6>> columns;
  for (const Contact& c : kept)
    append_cone_wrenches(scene, data, c, object, c_W, friction, cone_generators, &columns);
  double size = 1e-3;
  for (const auto& w : columns) size = std::max(size, w.tail<3>().norm());
  Eigen::MatrixXd A(6, columns.size());
  for (size_t j = 0; j < columns.size(); ++j) {
    A.col(Eigen::Index(j)) = columns[j];
    A.col(Eigen::Index(j)).tail<3>() /= size;  // torque rows in force units
  }
  const Eigen::Vector3d weight_W = model.total_mass * scene.gravity;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(6);
  b.head<3>() = -weight_W;  // the contacts carry the weight; no net moment about c
  Eigen::VectorXd x;
  return nonnegative_least_squares(A, b, &x) <= tolerance * weight_W.norm();
}

}  // namespace

double nonnegative_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                 Eigen::VectorXd* x) {
  const Eigen::Index n = A.cols();
  *x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(size_t(n), false);  // the set P of free (positive) variables
  const double eps = 1e-12 * std::max(1.0, A.norm() * b.norm());
  for (int outer = 0; outer < 3 * n + 10; ++outer) {
    const Eigen::VectorXd w = A.transpose() * (b - A * *x);  // the negative gradient
    Eigen::Index t = -1;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[size_t(j)] && w[j] > eps && (t < 0 || w[j] > w[t])) t = j;
    if (t < 0) break;  // Kuhn-Tucker conditions hold
    passive[size_t(t)] = true;
    for (int inner = 0; inner < 3 * n + 10; ++inner) {
      std::vector<Eigen::Index> P;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[size_t(j)]) P.push_back(j);
      Eigen::MatrixXd AP(A.rows(), Eigen::Index(P.size()));
      for (size_t k = 0; k < P.size(); ++k) AP.col(Eigen::Index(k)) = A.col(P[k]);
      const Eigen::VectorXd z = AP.colPivHouseholderQr().solve(b);
      double alpha = 1.0;
      for (size_t k = 0; k < P.size(); ++k)
        if (z[Eigen::Index(k)] <= 0.0) {
          const double gap = (*x)[P[k]] - z[Eigen::Index(k)];
          alpha = std::min(alpha, gap > 0.0 ? (*x)[P[k]] / gap : 0.0);
        }
      if (alpha >= 1.0) {  // z feasible: the new iterate
        for (size_t k = 0; k < P.size(); ++k) (*x)[P[k]] = z[Eigen::Index(k)];
        break;
      }
      for (size_t k = 0; k < P.size(); ++k) {  // step towards z to the first bound, free it
        double& v = (*x)[P[k]];
        v += alpha * (z[Eigen::Index(k)] - v);
        if (v <= 1e-15) v = 0.0, passive[size_t(P[k])] = false;
      }
    }
  }
  return (A * *x - b).norm();
}

bool objects_balance_without(const Scene& scene, const std::vector<ModelData>& data,
                             const Stance& stance, const Contact& removed, double friction,
                             int cone_generators, double tolerance) {
  for (const int object : {removed.s1.entity, removed.s2.entity}) {
    if (!tested_object(scene, object)) continue;
    std::vector<Contact> kept;
    bool bilateral = false;
    for (const Contact& c : stance.contacts()) {
      if (c.same_surfaces(removed) || (c.s1.entity != object && c.s2.entity != object)) continue;
      kept.push_back(c);
      bilateral = bilateral || c.bilateral;
    }
    if (kept.empty() || bilateral) continue;
    if (!object_balances(scene, data, kept, object, friction, cone_generators, tolerance))
      return false;
  }
  return true;
}

}  // namespace stanceplan
