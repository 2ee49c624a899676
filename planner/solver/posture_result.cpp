#include "planner/solver/posture_result.h"

#include <cmath>

namespace stanceplan {

const char* to_string(PostureStatus status) {
  switch (status) {
    case PostureStatus::Solved:
      return "solved";
    case PostureStatus::Infeasible:
      return "infeasible";
    case PostureStatus::IterationLimit:
      return "iteration_limit";
    case PostureStatus::NumericalFailure:
      return "numerical_failure";
  }
  return "?";
}

double residual_unit(const std::string& family) {
  if (family == "quaternion") return 1.0;
  if (family == "friction") return 0.1;
  return 1e-3;
}

std::string PostureResult::worst_family(double beyond) const {
  std::string worst;
  double value = -1.0;
  for (const auto& [family, residual] : residuals)
    if (residual > beyond && residual / residual_unit(family) > value) {
      value = residual / residual_unit(family);
      worst = family;
    }
  return worst;
}

std::string PostureResult::non_finite_part() const {
  for (int i = 0; i < q.size(); ++i)
    if (!std::isfinite(q[i])) return "q[" + std::to_string(i) + "]";
  for (size_t i = 0; i < forces.size(); ++i)
    if (!forces[i].force_W.allFinite() || !forces[i].point_W.allFinite())
      return "force " + std::to_string(i);
  for (size_t e = 0; e < torques.size(); ++e)
    if (!torques[e].allFinite()) return "torques of entity " + std::to_string(e);
  for (size_t i = 0; i < placements.size(); ++i)
    if (!std::isfinite(placements[i].x) || !std::isfinite(placements[i].y) ||
        !std::isfinite(placements[i].theta))
      return "placement " + std::to_string(i);
  return "";
}

}  // namespace stanceplan
