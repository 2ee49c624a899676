#pragma once
// A detour on the stance manifold (docs/METHOD.md section 7, "Motion between stances"), for a
// piece of a motion whose straight interpolation fails: an obstacle across it (a foot swung
// through a platform's edge, a finger through the ball) or the projection stuck in a local
// minimum behind one, so that the projected samples creep towards a point they never pass.
// A bidirectional RRT whose every node is a configuration projected into F_sigma by the same
// IK-statics program as the straight samples (CBiRRT, Berenson et al., ICRA 2009): one tree
// grows from the start (seeded with the straight samples already found), one from the goal; an
// extension moves its reference at most one spacing from its node and keeps the projection only
// when it lands within the spacing (so every edge is a valid pair of consecutive samples) and
// nearer its target (distances in units of the spacing over roots, joints and the points of the
// surfaces not held). Random targets are the straight path perturbed joint by joint (roots are
// left to the projection, which the held contacts fix). The path found is shortened by
// shortcuts (the same greedy extension between two of its nodes). Deterministic: our own
// generator, seeded for every plan() (std:: distributions differ between libraries).
#include <Eigen/Core>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "planner/motion/sample_spacing.h"
#include "planner/motion/stance_rrt_options.h"
#include "planner/plan/plan.h"

namespace stanceplan {

// Projects a configuration near `q_ref` into F_sigma, warm started from the node `from`; false
// when the projection fails.
using StanceProjector =
    std::function<bool(const MotionSample& from, const Eigen::VectorXd& q_ref, MotionSample* out)>;

struct StanceRrtResult {
  bool found = false;
  std::vector<MotionSample> path;  // strictly between start and goal, consecutive within spacing
  int projections = 0;
  int nodes = 0;
  std::string message;  // why no path ("" when found)
};

class StanceRrt {
 public:
  // `held`: the contacts every node holds at their placements (their surfaces' points never move
  // on the manifold, so distances leave them out).
  StanceRrt(const Scene& scene, SampleSpacing& spacing, const std::vector<Contact>& held,
            double joint_spacing, double point_spacing, StanceRrtOptions options);

  // A path from q_start to q_goal; `chain` (may be empty) holds samples from q_start on, each
  // within the spacing of its predecessor: the start tree's first branch.
  StanceRrtResult plan(const Eigen::VectorXd& q_start, const std::vector<MotionSample>& chain,
                       const Eigen::VectorXd& q_goal, const StanceProjector& project);

 private:
  struct Node {
    MotionSample sample;
    std::vector<Eigen::Vector3d> p_W;  // SampleSpacing::vertices
    int parent = -1;
  };
  using Tree = std::vector<Node>;

  // The spacing measure between two nodes (<= 1: consecutive samples).
  double ratio(const Node& a, const Node& b) const;
  // Between two nodes in units of the spacing: root positions and the points of surfaces not held
  // / point spacing, joints / joint spacing (Euclidean; `largest`: the largest term). For nearest
  // nodes and progress: a random target's held surfaces are not where the contacts hold them.
  double distance(const Node& a, const Node& b, double* largest) const;
  int nearest(const Tree& tree, const Node& target) const;
  void add(Tree* tree, MotionSample sample, int parent);
  // Greedy extensions of `tree` from node `from` towards `target`, each added to the tree: the
  // last node added (`from` when none), and whether it is within the spacing of the target.
  int connect(Tree* tree, int from, const Node& target, int max_steps, bool* reached);
  void random_target(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_goal, Node* out);
  double uniform();                                                    // [0, 1)
  std::vector<MotionSample> branch(const Tree& tree, int node) const;  // root excluded, to node
  void shortcut(std::vector<MotionSample>* path);                      // path with both ends

  const Scene& scene_;
  SampleSpacing& spacing_;
  std::vector<char> free_vertex_;  // per vertex of spacing_: on a surface not held
  double joint_spacing_, point_spacing_;
  StanceRrtOptions options_;
  const StanceProjector* project_ = nullptr;
  int projections_ = 0;
  int limit_ = 0;  // connect() projects while projections_ < limit_
  std::mt19937_64 rng_;
  Eigen::VectorXd q_ref_;
  Node target_;
};

}  // namespace stanceplan
