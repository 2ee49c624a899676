#pragma once
// Root orientation from the 4 quaternion components (w, x, y, z) of the configuration vector.
// R(phi) is the rotation of the normalised quaternion phi/|phi|, so that every iterate of the
// solver (where |phi| = 1 holds only at convergence) still maps to a proper rotation; the unit-norm
// constraint keeps phi on the sphere (docs/METHOD.md section 4).
#include <Eigen/Core>
#include <array>

namespace stanceplan {

Eigen::Matrix3d rotation_from_quaternion(const Eigen::Vector4d& wxyz);

// dR/dphi_k for k = 0..3 (w, x, y, z), including the normalisation (paper E27-E29 extended).
void rotation_quaternion_derivatives(const Eigen::Vector4d& wxyz,
                                     std::array<Eigen::Matrix3d, 4>* dR);

// d2R/dphi_a dphi_b for a, b = 0..3, including the normalisation; symmetric in (a, b).
void rotation_quaternion_second_derivatives(const Eigen::Vector4d& wxyz,
                                            std::array<std::array<Eigen::Matrix3d, 4>, 4>* d2R);

// The 4 x 4 Hessian d2(c . R(phi) x)/dphi2 for fixed c and x: what a contracted Hessian needs,
// without forming the 16 matrices.
Eigen::Matrix4d rotation_bilinear_hessian(const Eigen::Vector4d& wxyz, const Eigen::Vector3d& c,
                                          const Eigen::Vector3d& x);

}  // namespace stanceplan
