#include "planner/solver/posture_result.h"

namespace stanceplan {

const char* to_string(PostureStatus status) {
  switch (status) {
    case PostureStatus::Solved: return "solved";
    case PostureStatus::Infeasible: return "infeasible";
    case PostureStatus::IterationLimit: return "iteration_limit";
    case PostureStatus::NumericalFailure: return "numerical_failure";
  }
  return "?";
}

std::string PostureResult::worst_family() const {
  std::string worst;
  double value = -1.0;
  for (const auto& [family, residual] : residuals)
    if (residual > value) {
      value = residual;
      worst = family;
    }
  return worst;
}

}  // namespace stanceplan
