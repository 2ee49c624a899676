#pragma once
// The inverse-kinematics-and-statics solver of docs/METHOD.md section 4: one nonlinear program over
// (q, lambda) per call, solved by Ipopt with exact first derivatives. Thread-safe: solve() may be
// called from several threads (Ipopt itself is serialised inside the adapter).
#include <atomic>
#include <memory>
#include <vector>

#include "planner/scene/scene.h"
#include "planner/solver/hessian_cache.h"
#include "planner/solver/posture_request.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

class PostureSolver {
 public:
  PostureSolver(const Scene& scene, SolverOptions options);

  // Throws std::invalid_argument when the request is malformed (sizes, unknown surfaces, a
  // surface used twice, a contact within one link); every solver outcome is a status.
  PostureResult solve(const PostureRequest& request) const;
  // The same with the options' cancel flag replaced by `cancel` (a solve stops at its next
  // iteration once it is true): one solver can serve searches with flags of their own.
  PostureResult solve(const PostureRequest& request, const std::atomic<bool>* cancel) const;

  const SolverOptions& options() const { return options_; }
  const Scene& scene() const { return scene_; }

  // Throws std::invalid_argument when the request is malformed (what solve() checks first).
  void validate_request(const PostureRequest& request) const { validate(request); }

  // Candidate collision pairs that a request excludes: the links touching through its contacts.
  std::vector<bool> excluded_pairs(const PostureRequest& request) const;

 private:
  void validate(const PostureRequest& request) const;
  PostureResult solve_once(const PostureRequest& request, const SolverOptions& options) const;
  PostureResult solve_with(const PostureRequest& request, const SolverOptions& options) const;
  void diagnose(const PostureRequest& request, const SolverOptions& options,
                PostureResult& result) const;

  const Scene& scene_;
  SolverOptions options_;
  std::shared_ptr<HessianCache> hessian_cache_ = std::make_shared<HessianCache>();
};

// The realised placement of s1 in s2's frame at configuration q (E10-E13 read backwards).
Placement measure_placement(const Scene& scene, const Contact& contact, const Eigen::VectorXd& q);

}  // namespace stanceplan
