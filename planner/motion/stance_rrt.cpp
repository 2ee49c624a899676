#include "planner/motion/stance_rrt.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/motion/configuration_path.h"

namespace stanceplan {
namespace {
// An extension must bring its node nearer its target by this fraction of what its reference
// gained, else the tree is stuck there (against an obstacle, at a limit).
constexpr double kMinProgress = 0.25;
}  // namespace

StanceRrt::StanceRrt(const Scene& scene, SampleSpacing& spacing, const std::vector<Contact>& held,
                     double joint_spacing, double point_spacing, StanceRrtOptions options)
    : scene_(scene),
      spacing_(spacing),
      free_vertex_(size_t(spacing.num_vertices()), 1),
      joint_spacing_(joint_spacing),
      point_spacing_(point_spacing),
      options_(options) {
  q_ref_.resize(scene.system.nq());
  target_.sample.q.resize(scene.system.nq());
  for (int i = 0; i < spacing.num_vertices(); ++i)
    for (const Contact& c : held)
      if (spacing.vertex_surface(i) == c.s1 || spacing.vertex_surface(i) == c.s2)
        free_vertex_[size_t(i)] = 0;
}

double StanceRrt::uniform() {
  return double(rng_() >> 11) * 0x1.0p-53;
}

double StanceRrt::ratio(const Node& a, const Node& b) const {
  return spacing_.measure(a.sample.q, a.p_W, b.sample.q, b.p_W)
      .ratio(joint_spacing_, point_spacing_);
}

double StanceRrt::distance(const Node& na, const Node& nb, double* largest) const {
  const System& system = scene_.system;
  const Eigen::VectorXd &a = na.sample.q, &b = nb.sample.q;
  double sum = 0.0, most = 0.0;
  const auto add = [&](double d) {
    sum += d * d;
    most = std::max(most, std::abs(d));
  };
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.kind == EntityKind::Environment) continue;
    const int o = system.offset(e);
    if (entity.floating())
      for (int k = 0; k < 3; ++k) add((b[o + k] - a[o + k]) / point_spacing_);
    for (int k = entity.first_dof(); k < entity.nq(); ++k)
      add((b[o + k] - a[o + k]) / joint_spacing_);
  }
  for (size_t i = 0; i < free_vertex_.size(); ++i)
    if (free_vertex_[i]) add((nb.p_W[i] - na.p_W[i]).norm() / point_spacing_);
  if (largest) *largest = most;
  return std::sqrt(sum);
}

int StanceRrt::nearest(const Tree& tree, const Node& target) const {
  int best = 0;
  double best_distance = distance(tree[0], target, nullptr);
  for (int i = 1; i < int(tree.size()); ++i) {
    const double d = distance(tree[size_t(i)], target, nullptr);
    if (d < best_distance) best = i, best_distance = d;
  }
  return best;
}

void StanceRrt::add(Tree* tree, MotionSample sample, int parent) {
  Node& node = tree->emplace_back();
  node.sample = std::move(sample);
  node.parent = parent;
  spacing_.vertices(node.sample.q, &node.p_W);
}

int StanceRrt::connect(Tree* tree, int from, const Node& target, int max_steps, bool* reached) {
  int at = from;
  *reached = ratio((*tree)[size_t(at)], target) <= 1.0;
  Node next;
  for (int k = 0; k < max_steps && !*reached && projections_ < limit_; ++k) {
    const Node& here = (*tree)[size_t(at)];
    // The reference moves each coordinate at most `step` spacings (a landing too far, the
    // spacing being non-linear in the step, is tried closer, twice).
    double largest = 0.0;
    const double d = distance(here, target, &largest);
    double alpha = std::min(1.0, options_.step / std::max(largest, 1e-12));
    bool moved = false;
    for (int attempt = 0; attempt < 3 && !moved; ++attempt, alpha *= 0.5) {
      interpolate_configuration(scene_.system, here.sample.q, target.sample.q, alpha, q_ref_);
      ++projections_;
      if (!(*project_)(here.sample, q_ref_, &next.sample)) break;
      spacing_.vertices(next.sample.q, &next.p_W);
      if (ratio(here, next) > 1.0) continue;
      // Progress: at least kMinProgress of what the reference gained.
      if (distance(next, target, nullptr) > d - kMinProgress * alpha * d) break;
      next.parent = at;
      tree->push_back(std::move(next));
      next = Node{};
      at = int(tree->size()) - 1;
      moved = true;
      *reached = ratio(tree->back(), target) <= 1.0;
    }
    if (!moved) break;
  }
  return at;
}

void StanceRrt::random_target(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_goal,
                              Node* out) {
  const System& system = scene_.system;
  interpolate_configuration(system, q_start, q_goal, uniform(), out->sample.q);
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.kind == EntityKind::Environment) continue;
    const int first = system.offset(e) + entity.first_dof();
    for (int k = 0; k < entity.model->num_dofs(); ++k) {
      const Joint& joint = entity.model->joints[size_t(entity.model->dof_joints[size_t(k)])];
      double& v = out->sample.q[first + k];
      v += options_.spread * (2.0 * uniform() - 1.0);
      if (joint.has_position_limits) v = std::clamp(v, joint.lower, joint.upper);
    }
  }
  spacing_.vertices(out->sample.q, &out->p_W);
}

std::vector<MotionSample> StanceRrt::branch(const Tree& tree, int node) const {
  std::vector<MotionSample> out;
  for (int i = node; i > 0; i = tree[size_t(i)].parent) out.push_back(tree[size_t(i)].sample);
  std::reverse(out.begin(), out.end());
  return out;
}

void StanceRrt::shortcut(std::vector<MotionSample>* path) {
  limit_ = projections_ + options_.max_shortcut_projections;  // its own budget, after the search
  for (int attempt = 0; attempt < options_.shortcut_attempts; ++attempt) {
    const int n = int(path->size());
    if (n < 4 || projections_ >= limit_) return;
    int i = int(uniform() * n), j = int(uniform() * n);
    if (i > j) std::swap(i, j);
    if (j - i < 3) continue;
    Tree tree;
    add(&tree, (*path)[size_t(i)], -1);
    Node end;
    end.sample.q = (*path)[size_t(j)].q;
    spacing_.vertices(end.sample.q, &end.p_W);
    bool reached = false;
    const int last = connect(&tree, 0, end, j - i - 2, &reached);
    if (!reached) continue;
    std::vector<MotionSample> between = branch(tree, last);
    path->erase(path->begin() + i + 1, path->begin() + j);
    path->insert(path->begin() + i + 1, std::make_move_iterator(between.begin()),
                 std::make_move_iterator(between.end()));
  }
}

StanceRrtResult StanceRrt::plan(const Eigen::VectorXd& q_start,
                                const std::vector<MotionSample>& chain,
                                const Eigen::VectorXd& q_goal, const StanceProjector& project) {
  rng_.seed(options_.seed);
  projections_ = 0;
  limit_ = options_.max_projections;
  project_ = &project;
  Tree trees[2];
  trees[0].reserve(chain.size() + 256);
  trees[1].reserve(256);
  add(&trees[0], MotionSample{q_start, {}, {}}, -1);
  for (const MotionSample& s : chain) add(&trees[0], s, int(trees[0].size()) - 1);
  add(&trees[1], MotionSample{q_goal, {}, {}}, -1);
  StanceRrtResult out;
  // First the goal tree straight towards the end of the start chain (the straight path run
  // backwards), then random targets, the trees taking turns.
  int side = 0;
  bool reached = false;
  int a = int(trees[0].size()) - 1;
  int b = -1;
  for (int round = 0; projections_ < options_.max_projections; ++round) {
    Tree& grow = trees[side];
    Tree& other = trees[1 - side];
    if (round > 0) {
      random_target(q_start, q_goal, &target_);
      a = connect(&grow, nearest(grow, target_), target_, options_.max_connect_steps, &reached);
    } else {
      a = int(grow.size()) - 1;
    }
    const Node towards = grow[size_t(a)];
    b = connect(&other, nearest(other, towards), towards, options_.max_connect_steps, &reached);
    if (reached) break;
    side = 1 - side;
  }
  out.nodes = int(trees[0].size() + trees[1].size());
  if (!reached) {
    out.projections = projections_;
    out.message = "no detour within " + std::to_string(options_.max_projections) +
                  " projections (" + std::to_string(out.nodes) + " nodes)";
    return out;
  }
  const int start_node = side == 0 ? a : b, goal_node = side == 0 ? b : a;
  std::vector<MotionSample> path = branch(trees[0], start_node);
  std::vector<MotionSample> back = branch(trees[1], goal_node);
  path.insert(path.begin(), MotionSample{q_start, {}, {}});
  path.insert(path.end(), std::make_move_iterator(back.rbegin()),
              std::make_move_iterator(back.rend()));
  path.push_back(MotionSample{q_goal, {}, {}});
  shortcut(&path);
  out.path.assign(std::make_move_iterator(path.begin() + 1),
                  std::make_move_iterator(path.end() - 1));
  out.found = true;
  out.projections = projections_;
  return out;
}

}  // namespace stanceplan
