#include "planner/solver/ipopt_adapter.h"

#include <IpIpoptApplication.hpp>
#include <IpJournalist.hpp>
#include <IpOptionsList.hpp>
#include <IpRegOptions.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

namespace stanceplan {
namespace {

// Derivatives with a NaN or an infinity (a degenerate geometry at the iterate) are reported to
// Ipopt as an evaluation error, so that it never computes a step from them.
bool all_finite(const Ipopt::Number* values, Ipopt::Index count) {
  for (Ipopt::Index i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) return false;
  return true;
}

std::mutex& ipopt_mutex() {
  static std::mutex mutex;
  return mutex;
}

// A fresh application for one run that shares Ipopt's table of registered options: building that
// table (and freeing it) is most of what IpoptApplicationFactory costs, about a tenth of a warm
// motion projection's Ipopt time (perf, the table's motion). The table is never written after
// registration; the options list, journalist and algorithm are the run's own, so no setting or
// state passes from one run to the next. Call with ipopt_mutex() held.
Ipopt::SmartPtr<Ipopt::IpoptApplication> new_application() {
  static const Ipopt::SmartPtr<Ipopt::RegisteredOptions> registered = [] {
    const Ipopt::SmartPtr<Ipopt::IpoptApplication> first = IpoptApplicationFactory();
    return first->RegOptions();
  }();
  // As IpoptApplication's own constructor: console output at print_level (set by Initialize).
  Ipopt::SmartPtr<Ipopt::Journalist> journalist = new Ipopt::Journalist();
  journalist->AddFileJournal("console", "stdout", Ipopt::J_ITERSUMMARY)
      ->SetPrintLevel(Ipopt::J_DBG, Ipopt::J_NONE);
  Ipopt::SmartPtr<Ipopt::OptionsList> options = new Ipopt::OptionsList(registered, journalist);
  return new Ipopt::IpoptApplication(registered, options, journalist);
}

class PostureTnlp : public Ipopt::TNLP {
 public:
  PostureTnlp(PostureNlp& nlp, const SolverOptions& options) : nlp_(nlp), options_(options) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac_g,
                    Ipopt::Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = nlp_.n();
    m = nlp_.m();
    nnz_jac_g = nlp_.nnz();
    nnz_h_lag = options_.hessian != HessianMode::LimitedMemory ? nlp_.hessian_nnz() : 0;
    index_style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index,
                       Ipopt::Number* g_l, Ipopt::Number* g_u) override {
    nlp_.variable_bounds(x_l, x_u);
    nlp_.constraint_bounds(g_l, g_u);
    return true;
  }
  bool get_starting_point(Ipopt::Index, bool init_x, Ipopt::Number* x, bool init_z, Ipopt::Number*,
                          Ipopt::Number*, Ipopt::Index, bool init_lambda, Ipopt::Number*) override {
    if (init_z || init_lambda) return false;
    if (init_x) nlp_.starting_point(x);
    return true;
  }
  bool eval_f(Ipopt::Index, const Ipopt::Number* x, bool new_x, Ipopt::Number& f) override {
    f = nlp_.objective(x, new_x);
    return std::isfinite(f);
  }
  bool eval_grad_f(Ipopt::Index n, const Ipopt::Number* x, bool new_x,
                   Ipopt::Number* grad) override {
    nlp_.objective_gradient(x, new_x, grad);
    return all_finite(grad, n);
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number* x, bool new_x, Ipopt::Index m,
              Ipopt::Number* g) override {
    nlp_.constraints(x, new_x, g);
    for (int i = 0; i < m; ++i)
      if (!std::isfinite(g[i])) return false;  // Ipopt backs off instead of using a NaN
    return true;
  }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number* x, bool new_x, Ipopt::Index,
                  Ipopt::Index nele_jac, Ipopt::Index* rows, Ipopt::Index* cols,
                  Ipopt::Number* values) override {
    if (values == nullptr) {
      nlp_.structure(rows, cols);
      return true;
    }
    nlp_.jacobian_values(x, new_x, values);
    return all_finite(values, nele_jac);  // Ipopt stops on it instead of stepping to NaN
  }
  // Variable scaling: the contact force coefficients are in newtons (tens to hundreds), q in
  // metres and radians. Scaling lambda by the expected coefficient per vertex makes them O(1),
  // which the limited-memory Hessian needs. Constraint rows are already normalised by the blocks
  // (equilibrium by m|g|, torques by the effort limit), so they are left unscaled.
  bool get_scaling_parameters(Ipopt::Number& obj_scaling, bool& use_x_scaling, Ipopt::Index n,
                              Ipopt::Number* x_scaling, bool& use_g_scaling, Ipopt::Index,
                              Ipopt::Number*) override {
    obj_scaling = 1.0;
    use_x_scaling = true;
    use_g_scaling = false;
    std::vector<double> x0(n);
    nlp_.starting_point(x0.data());
    for (int i = 0; i < n; ++i) x_scaling[i] = 1.0;
    for (int i = nlp_.layout().nq; i < n; ++i) x_scaling[i] = 1.0 / std::max(1.0, std::abs(x0[i]));
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index n, const Ipopt::Number* x,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Index,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Number obj_value,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    final_x = Eigen::Map<const Eigen::VectorXd>(x, n);
    final_objective = obj_value;
  }

  bool eval_h(Ipopt::Index, const Ipopt::Number* x, bool new_x, Ipopt::Number obj_factor,
              Ipopt::Index, const Ipopt::Number* lambda, bool, Ipopt::Index nele_hess,
              Ipopt::Index* rows, Ipopt::Index* cols, Ipopt::Number* values) override {
    if (options_.hessian == HessianMode::LimitedMemory) return false;
    if (values == nullptr) {
      nlp_.hessian_structure(rows, cols);
      return true;
    }
    nlp_.hessian_values(x, new_x, obj_factor, lambda, values);
    return all_finite(values, nele_hess);
  }

  // Between iterations: the search's cancel flag, then the stall rule on the constraint violation.
  bool intermediate_callback(Ipopt::AlgorithmMode, Ipopt::Index iteration, Ipopt::Number,
                             Ipopt::Number inf_pr, Ipopt::Number, Ipopt::Number, Ipopt::Number,
                             Ipopt::Number, Ipopt::Number, Ipopt::Number, Ipopt::Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    if (options_.cancel && options_.cancel->load()) return false;
    stalled = stall_.stalled(iteration, inf_pr);
    return !stalled;
  }

  Eigen::VectorXd final_x;
  double final_objective = 0.0;
  bool stalled = false;
  const std::string& stall_reason() const { return stall_.reason(); }

 private:
  PostureNlp& nlp_;
  const SolverOptions& options_;
  StallMonitor stall_{options_.stall, options_.max_iterations};
};

struct StatusInfo {
  PostureStatus status;
  const char* name;
};

StatusInfo classify(Ipopt::ApplicationReturnStatus s) {
  using A = Ipopt::ApplicationReturnStatus;
  switch (s) {
    case A::Solve_Succeeded:
      return {PostureStatus::Solved, "Solve_Succeeded"};
    case A::Solved_To_Acceptable_Level:
      return {PostureStatus::Solved, "Solved_To_Acceptable_Level"};
    case A::Infeasible_Problem_Detected:
      return {PostureStatus::Infeasible, "Infeasible_Problem_Detected"};
    case A::Restoration_Failed:
      return {PostureStatus::Infeasible, "Restoration_Failed"};
    case A::Maximum_Iterations_Exceeded:
      return {PostureStatus::IterationLimit, "Maximum_Iterations_Exceeded"};
    case A::Maximum_CpuTime_Exceeded:
      return {PostureStatus::IterationLimit, "Maximum_CpuTime_Exceeded"};
    case A::Search_Direction_Becomes_Too_Small:
      return {PostureStatus::NumericalFailure, "Search_Direction_Becomes_Too_Small"};
    case A::Diverging_Iterates:
      return {PostureStatus::NumericalFailure, "Diverging_Iterates"};
    case A::Error_In_Step_Computation:
      return {PostureStatus::NumericalFailure, "Error_In_Step_Computation"};
    case A::Invalid_Number_Detected:
      return {PostureStatus::NumericalFailure, "Invalid_Number_Detected"};
    case A::Not_Enough_Degrees_Of_Freedom:
      return {PostureStatus::NumericalFailure, "Not_Enough_Degrees_Of_Freedom"};
    case A::User_Requested_Stop:
      return {PostureStatus::NumericalFailure, "cancelled"};
    default:
      return {PostureStatus::NumericalFailure, "Ipopt_Error"};
  }
}

void set_options(Ipopt::IpoptApplication& app, const SolverOptions& options,
                 const std::string& report) {
  Ipopt::OptionsList& o = *app.Options();
  o.SetIntegerValue("print_level", options.print_level);
  o.SetStringValue("sb", "yes");  // no banner
  o.SetStringValue("hessian_approximation",
                   options.hessian == HessianMode::LimitedMemory ? "limited-memory" : "exact");
  o.SetStringValue("linear_solver", "mumps");
  // Measured (bench/solver_bench): the adaptive barrier update needs 7-12 iterations where the
  // monotone one needs 11-15, with the finite-difference Hessian.
  o.SetStringValue("mu_strategy", "adaptive");
  o.SetStringValue("nlp_scaling_method", "user-scaling");
  // Feasibility is what a posture must have (tolerance); optimality of the regularising objective
  // only needs to be approximate, so the overall tolerance is looser.
  o.SetNumericValue("tol", options.optimality_tolerance);
  o.SetNumericValue("dual_inf_tol", options.optimality_tolerance);
  o.SetNumericValue("constr_viol_tol", options.tolerance);
  o.SetNumericValue("compl_inf_tol", options.complementarity_tolerance);
  o.SetNumericValue("acceptable_tol", 10.0 * options.optimality_tolerance);
  o.SetIntegerValue("acceptable_iter", 5);
  o.SetNumericValue("acceptable_constr_viol_tol", options.tolerance);
  o.SetNumericValue("acceptable_compl_inf_tol", options.complementarity_tolerance);
  // Iterative refinement only when a solve's residual asks for it (Ipopt still refines then):
  // measured with bench/solver_bench, one MUMPS back-solve less per step.
  o.SetIntegerValue("min_refinement_steps", 0);
  o.SetIntegerValue("max_iter", options.max_iterations);
  o.SetNumericValue("bound_relax_factor", 0.0);  // joint limits are hard
  for (const auto& [name, value] : options.ipopt_options) {
    char* end = nullptr;
    const long integer = std::strtol(value.c_str(), &end, 10);
    if (end && *end == '\0' && !value.empty()) {
      o.SetIntegerValue(name, static_cast<Ipopt::Index>(integer));
      continue;
    }
    const double number = std::strtod(value.c_str(), &end);
    if (end && *end == '\0' && !value.empty())
      o.SetNumericValue(name, number);
    else
      o.SetStringValue(name, value);
  }
  if (options.derivative_test) {
    o.SetStringValue("derivative_test", "first-order");
    o.SetNumericValue("derivative_test_tol", 1e-4);
    o.SetNumericValue("derivative_test_perturbation", 1e-7);
    o.SetStringValue("output_file", report);
    o.SetIntegerValue("file_print_level", 4);
  }
}

}  // namespace

IpoptRun run_ipopt(PostureNlp& nlp, const SolverOptions& options) {
  std::lock_guard<std::mutex> lock(ipopt_mutex());
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = new_application();
  // Where the derivative checker writes (derivative_test only).
  const std::string report = options.derivative_test
                                 ? (std::filesystem::temp_directory_path() /
                                    ("stanceplan_ipopt_" + std::to_string(getpid()) + ".txt"))
                                       .string()
                                 : std::string();
  set_options(*app, options, report);
  IpoptRun run;
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    run.message = "Ipopt could not be initialised";
    return run;
  }
  Ipopt::SmartPtr<PostureTnlp> tnlp = new PostureTnlp(nlp, options);
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(tnlp);
  const StatusInfo info = classify(status);
  run.status = info.status;
  run.message = info.name;
  if (status == Ipopt::User_Requested_Stop && tnlp->stalled) {
    run.status = PostureStatus::IterationLimit;
    run.message = "Stalled (" + tnlp->stall_reason() + ")";
  }
  if (Ipopt::IsValid(app->Statistics())) run.iterations = app->Statistics()->IterationCount();
  run.x = tnlp->final_x.size() == nlp.n() ? tnlp->final_x : Eigen::VectorXd();
  run.objective = tnlp->final_objective;
  if (options.derivative_test) {
    std::ifstream in(report);
    std::stringstream text;
    text << in.rdbuf();
    run.derivative_report = text.str();
    std::filesystem::remove(report);
  }
  return run;
}

}  // namespace stanceplan
