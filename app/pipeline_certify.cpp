// Certifying a plan file (app/pipeline.h).
#include <iomanip>
#include <ostream>

#include "app/pipeline.h"
#include "planner/certify/certify.h"

namespace stanceplan::app {

int certify_file(const std::string& path, std::ostream& out, std::ostream& err) {
  const LoadedPlan plan = read_plan(path);
  const CertifyReport report = certify(plan);
  out << "certify " << path << ": " << plan.plan.steps.size() << " steps\n";
  if (!plan.plan.partial.empty())
    out << "partial plan (" << plan.plan.partial
        << "): every step is checked; the last stance is not the goal\n";
  out << std::left << std::setw(20) << "check" << std::right << std::setw(12) << "worst"
      << std::setw(12) << "tolerance"
      << "  unit     step  result  where\n";
  for (const CheckResult& c : report.checks) {
    out << std::left << std::setw(20) << c.name << std::right << std::scientific
        << std::setprecision(2) << std::setw(12) << c.worst << std::setw(12) << c.tolerance << "  "
        << std::left << std::setw(8) << c.unit << std::right << std::setw(5) << c.step << "  "
        << (c.passed() ? "ok    " : "FAILED") << "  " << (c.passed() ? "" : c.detail) << "\n";
  }
  if (!report.passed()) {
    for (const CheckResult& c : report.checks)
      if (!c.passed())
        err << "stanceplan: certification failed: " << c.name << " at step " << c.step << ": "
            << c.detail << "\n";
    return kExitFailed;
  }
  out << "all checks passed\n";
  return kExitSuccess;
}

}  // namespace stanceplan::app
