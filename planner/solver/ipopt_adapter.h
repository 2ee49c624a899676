#pragma once
// Runs Ipopt on a PostureNlp. The only place that includes Ipopt's headers. Ipopt 3.11 with
// MUMPS is not thread-safe (docs/DEPENDENCIES.md section 1): every solve of the process holds one
// mutex, so callers on several threads are serialised here.
#include <Eigen/Core>
#include <string>

#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

struct IpoptRun {
  PostureStatus status = PostureStatus::NumericalFailure;
  std::string message;  // Ipopt's return status, by name
  int iterations = 0;
  double objective = 0.0;
  Eigen::VectorXd x;              // the final iterate
  std::string derivative_report;  // Ipopt's derivative checker output (derivative_test only)
};

IpoptRun run_ipopt(PostureNlp& nlp, const SolverOptions& options);

}  // namespace stanceplan
