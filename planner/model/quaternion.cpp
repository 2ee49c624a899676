#include "planner/model/quaternion.h"

namespace stanceplan {
namespace {

// Rotation of a unit quaternion u = (w, x, y, z), and its derivatives with respect to u's
// components (the polynomial form, valid for |u| = 1).
Eigen::Matrix3d rotation_of_unit(const Eigen::Vector4d& u) {
  const double w = u[0], x = u[1], y = u[2], z = u[3];
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

void unit_derivatives(const Eigen::Vector4d& u, std::array<Eigen::Matrix3d, 4>* dR) {
  const double w = u[0], x = u[1], y = u[2], z = u[3];
  (*dR)[0] << 0, -2 * z, 2 * y, 2 * z, 0, -2 * x, -2 * y, 2 * x, 0;
  (*dR)[1] << 0, 2 * y, 2 * z, 2 * y, -4 * x, -2 * w, 2 * z, 2 * w, -4 * x;
  (*dR)[2] << -4 * y, 2 * x, 2 * w, 2 * x, 0, 2 * z, -2 * w, 2 * z, -4 * y;
  (*dR)[3] << -4 * z, -2 * w, 2 * x, 2 * w, -4 * z, 2 * y, 2 * x, 2 * y, 0;
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

}  // namespace stanceplan
