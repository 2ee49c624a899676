#pragma once
// Environment switches that change the solver's options in the benchmarks, for experiments (what
// does the analytic Hessian, the torque or polygon active set, the balanced start give?):
//   STANCEPLAN_HESSIAN=fd|analytic|lbfgs     how Ipopt gets second derivatives
//   STANCEPLAN_NO_TORQUE=1                    without the torque objective (E24)
//   STANCEPLAN_NO_TORQUE_LIMITS=1             without E19
//   STANCEPLAN_TORQUE_ACTIVE=f                SolverOptions::torque_active_fraction
//   STANCEPLAN_POLYGON_ACTIVE=d               SolverOptions::polygon_active_distance ("inf": all)
//   STANCEPLAN_NO_BALANCE=1                   even shares instead of balanced starting forces
//   STANCEPLAN_STALL_AFTER=n                  SolverOptions::stall.after (0: no stall rule)
//   STANCEPLAN_IPOPT="name=value,..."         Ipopt options passed through
#include <algorithm>
#include <cstdlib>
#include <string>

#include "planner/solver/posture_request.h"

namespace stanceplan::bench {

inline void apply_solver_switches(SolverOptions& o) {
  if (const char* h = std::getenv("STANCEPLAN_HESSIAN")) {
    const std::string mode = h;
    if (mode == "lbfgs") o.hessian = HessianMode::LimitedMemory;
    if (mode == "fd") o.hessian = HessianMode::FiniteDifference;
    if (mode == "analytic") o.hessian = HessianMode::Analytic;
  }
  if (std::getenv("STANCEPLAN_NO_TORQUE")) o.w_torque = 0.0;
  if (std::getenv("STANCEPLAN_NO_TORQUE_LIMITS")) o.enforce_torque_limits = false;
  if (const char* f = std::getenv("STANCEPLAN_TORQUE_ACTIVE"))
    o.torque_active_fraction = std::atof(f);
  if (const char* d = std::getenv("STANCEPLAN_POLYGON_ACTIVE"))
    o.polygon_active_distance = std::atof(d);
  if (std::getenv("STANCEPLAN_NO_BALANCE")) o.balance_starting_forces = false;
  if (const char* n = std::getenv("STANCEPLAN_STALL_AFTER")) o.stall.after = std::atoi(n);
  if (const char* env = std::getenv("STANCEPLAN_IPOPT")) {
    const std::string text = env;
    size_t start = 0;
    while (start < text.size()) {
      const size_t end = std::min(text.find(',', start), text.size());
      const std::string item = text.substr(start, end - start);
      const size_t eq = item.find('=');
      if (eq != std::string::npos)
        o.ipopt_options.emplace_back(item.substr(0, eq), item.substr(eq + 1));
      start = end + 1;
    }
  }
}

}  // namespace stanceplan::bench
