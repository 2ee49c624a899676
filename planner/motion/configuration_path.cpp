#include "planner/motion/configuration_path.h"

#include <Eigen/Geometry>

namespace stanceplan {

void interpolate_configuration(const System& system, const Eigen::VectorXd& q_a,
                               const Eigen::VectorXd& q_b, double s, Eigen::VectorXd& q_out) {
  q_out = (1.0 - s) * q_a + s * q_b;
  for (int e = 0; e < system.num_entities(); ++e) {
    if (!system.entity(e).floating()) continue;
    const int o = system.offset(e) + Entity::kBaseQuaternion;
    const Eigen::Quaterniond a(q_a[o], q_a[o + 1], q_a[o + 2], q_a[o + 3]);
    const Eigen::Quaterniond b(q_b[o], q_b[o + 1], q_b[o + 2], q_b[o + 3]);
    const Eigen::Quaterniond q = a.normalized().slerp(s, b.normalized()).normalized();
    q_out.segment<4>(o) << q.w(), q.x(), q.y(), q.z();
  }
}

}  // namespace stanceplan
