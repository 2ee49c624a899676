#include "app/plan_output.h"

#include <iomanip>
#include <ostream>
#include <sstream>

#include "app/exit_codes.h"
#include "planner/io/plan_writer.h"

namespace stanceplan::app {
namespace {

// "interpenetration at step 7: robot/l_knee and env/chair (2.00e-02 m, tolerance 1.00e-03 m)"
std::string describe(const CheckResult& c) {
  std::ostringstream out;
  out << c.name << " at step " << c.step << ": " << c.detail << " (" << std::scientific
      << std::setprecision(2) << c.worst << (c.unit.empty() ? "" : " " + c.unit) << ", tolerance "
      << c.tolerance << (c.unit.empty() ? "" : " " + c.unit) << ")";
  return out.str();
}

}  // namespace

CertifyReport certify_in_memory(const Plan& plan, const Scenario& scenario, std::ostream& err) {
  CertifyReport report = certify(scenario.scene, scenario.solver.friction, plan);
  for (const CheckResult& c : report.checks)
    if (!c.passed()) err << "stanceplan: certification failed: " << describe(c) << "\n";
  return report;
}

int write_certified_plan(Plan plan, const Scenario& scenario, const std::string& path, bool partial,
                         std::ostream& err) {
  const CertifyReport report = certify_in_memory(plan, scenario, err);
  if (report.passed()) {
    write_plan(plan, scenario, path);
    return kExitSuccess;
  }
  const int first = report.first_failed_step;
  err << "stanceplan: the plan fails certification"
      << (first >= 0 ? " from step " + std::to_string(first) : std::string()) << "; " << path
      << " not written\n";
  if (!partial || first <= 0) return kExitFailed;
  const std::string why = "certification failed from step " + std::to_string(first) + " (" +
                          describe(*report.first_failure()) + ")";
  plan.steps.resize(size_t(first));
  plan.partial = plan.partial.empty() ? why : plan.partial + "; " + why;
  write_plan(plan, scenario, path);
  err << "stanceplan: wrote a PARTIAL plan to " << path << ": the " << first
      << " certified steps before step " << first << "\n";
  return kExitFailed;
}

}  // namespace stanceplan::app
