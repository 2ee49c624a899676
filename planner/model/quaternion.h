#pragma once
// Root orientation from the 4 quaternion components (w, x, y, z) of the configuration vector.
// R(phi) is the rotation of the normalised quaternion phi/|phi|, so that every iterate of the
// solver (where |phi| = 1 holds only at convergence) still maps to a proper rotation; the unit-norm
// constraint keeps phi on the sphere (METHOD.md section 4).
#include <Eigen/Core>
#include <array>

namespace stanceplan {

Eigen::Matrix3d rotation_from_quaternion(const Eigen::Vector4d& wxyz);

// dR/dphi_k for k = 0..3 (w, x, y, z), including the normalisation (paper E27-E29 extended).
void rotation_quaternion_derivatives(const Eigen::Vector4d& wxyz,
                                     std::array<Eigen::Matrix3d, 4>* dR);

}  // namespace stanceplan
