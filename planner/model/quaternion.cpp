#include "planner/model/quaternion.h"

#include <Eigen/Geometry>

namespace stanceplan {
namespace {

// Rotation of a unit quaternion u = (w, x, y, z), and its derivatives with respect to u's
// components (the polynomial form, valid for |u| = 1).
Eigen::Matrix3d rotation_of_unit(const Eigen::Vector4d& u) {
  const double w = u[0], x = u[1], y = u[2], z = u[3];
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z),
      1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x),
      1 - 2 * (x * x + y * y);
  return R;
}

void unit_derivatives(const Eigen::Vector4d& u, std::array<Eigen::Matrix3d, 4>* dR) {
  const double w = u[0], x = u[1], y = u[2], z = u[3];
  (*dR)[0] << 0, -2 * z, 2 * y, 2 * z, 0, -2 * x, -2 * y, 2 * x, 0;
  (*dR)[1] << 0, 2 * y, 2 * z, 2 * y, -4 * x, -2 * w, 2 * z, 2 * w, -4 * x;
  (*dR)[2] << -4 * y, 2 * x, 2 * w, 2 * x, 0, 2 * z, -2 * w, 2 * z, -4 * y;
  (*dR)[3] << -4 * z, -2 * w, 2 * x, 2 * w, -4 * z, 2 * y, 2 * x, 2 * y, 0;
}

// The homogeneous form Rh(phi): every entry a quadratic form in phi, equal to R(phi) on the unit
// sphere. Hence R(phi) = Rh(phi) / |phi|^2 everywhere, a quotient whose derivatives of any order
// are plain (no projection onto the sphere needed). dRh/dphi_a is linear in phi.
Eigen::Matrix3d homogeneous_rotation(const Eigen::Vector4d& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Eigen::Matrix3d R;
  // clang-format off
  R << w * w + x * x - y * y - z * z, 2 * (x * y - w * z),           2 * (x * z + w * y),
       2 * (x * y + w * z),           w * w - x * x + y * y - z * z, 2 * (y * z - w * x),
       2 * (x * z - w * y),           2 * (y * z + w * x),           w * w - x * x - y * y + z * z;
  // clang-format on
  return R;
}

Eigen::Matrix3d homogeneous_derivative(int a, const Eigen::Vector4d& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Eigen::Matrix3d D;
  switch (a) {
    case 0:
      D << w, -z, y, z, w, -x, -y, x, w;
      break;
    case 1:
      D << x, y, z, y, -x, -w, z, w, -x;
      break;
    case 2:
      D << -y, x, w, x, y, z, -w, z, -y;
      break;
    default:
      D << -z, -w, x, w, -z, y, x, y, z;
      break;
  }
  return 2 * D;
}

}  // namespace

Eigen::Matrix3d rotation_from_quaternion(const Eigen::Vector4d& wxyz) {
  return rotation_of_unit(wxyz / wxyz.norm());
}

void rotation_quaternion_derivatives(const Eigen::Vector4d& wxyz,
                                     std::array<Eigen::Matrix3d, 4>* dR) {
  // Chain rule through u = phi / |phi|: du/dphi = (I - u u^T) / |phi|.
  const double norm = wxyz.norm();
  const Eigen::Vector4d u = wxyz / norm;
  std::array<Eigen::Matrix3d, 4> dR_du;
  unit_derivatives(u, &dR_du);
  const Eigen::Matrix4d du_dphi = (Eigen::Matrix4d::Identity() - u * u.transpose()) / norm;
  for (int i = 0; i < 4; ++i) {
    (*dR)[i].setZero();
    for (int k = 0; k < 4; ++k) (*dR)[i] += dR_du[k] * du_dphi(k, i);
  }
}

void rotation_quaternion_second_derivatives(const Eigen::Vector4d& wxyz,
                                            std::array<std::array<Eigen::Matrix3d, 4>, 4>* d2R) {
  // R = Rh / s with s = |phi|^2:
  // d2R_ab = Rh_ab / s - 2 (Rh_a phi_b + Rh_b phi_a) / s^2 - 2 delta_ab Rh / s^2
  //          + 8 Rh phi_a phi_b / s^3,
  // Rh_a linear in phi, so Rh_ab = Rh_a evaluated at the unit vector e_b.
  const double s = wxyz.squaredNorm();
  const Eigen::Matrix3d Rh = homogeneous_rotation(wxyz);
  std::array<Eigen::Matrix3d, 4> Rh_a;
  for (int a = 0; a < 4; ++a) Rh_a[a] = homogeneous_derivative(a, wxyz);
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      Eigen::Matrix3d D = homogeneous_derivative(a, Eigen::Vector4d::Unit(b)) / s -
                          2 * (Rh_a[a] * wxyz[b] + Rh_a[b] * wxyz[a]) / (s * s) +
                          8 * wxyz[a] * wxyz[b] / (s * s * s) * Rh;
      if (a == b) D -= 2 / (s * s) * Rh;
      (*d2R)[a][b] = D;
      (*d2R)[b][a] = D;
    }
}

Eigen::Matrix4d rotation_bilinear_hessian(const Eigen::Vector4d& wxyz, const Eigen::Vector3d& c,
                                          const Eigen::Vector3d& x) {
  // c . Rh(phi) x = phi^T Q phi: with phi = (w, v), Rh x = (w^2 - v.v) x + 2 (v.x) v + 2 w v x x,
  // so Q = [c.x, (x x c)^T; x x c, x c^T + c x^T - (c.x) I]. Then f = g / s with g = phi^T Q phi,
  // s = |phi|^2 (a Rayleigh quotient) and
  // d2f = 2 Q / s - 4 (Q phi phi^T + phi phi^T Q) / s^2 - 2 g I / s^2 + 8 g phi phi^T / s^3.
  const double cx = c.dot(x);
  Eigen::Matrix4d Q;
  Q(0, 0) = cx;
  Q.block<3, 1>(1, 0) = x.cross(c);
  Q.block<1, 3>(0, 1) = x.cross(c).transpose();
  Q.block<3, 3>(1, 1) = x * c.transpose() + c * x.transpose() - cx * Eigen::Matrix3d::Identity();
  const double s = wxyz.squaredNorm();
  const Eigen::Vector4d Qphi = Q * wxyz;
  const double g = wxyz.dot(Qphi);
  const Eigen::Matrix4d cross_terms = Qphi * wxyz.transpose();
  Eigen::Matrix4d H = 2 / s * Q - 4 / (s * s) * (cross_terms + cross_terms.transpose()) +
                      8 * g / (s * s * s) * wxyz * wxyz.transpose();
  H.diagonal().array() -= 2 * g / (s * s);
  // Rounding differs between the two triangles' sums; the callers rely on exact symmetry.
  return 0.5 * (H + H.transpose());
}

}  // namespace stanceplan
