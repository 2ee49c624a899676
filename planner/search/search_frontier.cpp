// The tree and its frontier (search_run.h): what a node costs, when it is the goal, when it is
// already in the tree, which node is closest to the goal, and the milestones the tree reaches.
#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/plan/plan_step.h"
#include "planner/search/search_event_builders.h"
#include "planner/search/search_run.h"
#include "planner/search/step_target.h"

namespace stanceplan {
namespace {

// Two placements of one contact within the search's tolerances.
bool same_placement(const Placement& a, const Placement& b, const SearchOptions& options) {
  return std::abs(a.x - b.x) <= options.placement_tolerance &&
         std::abs(a.y - b.y) <= options.placement_tolerance &&
         std::abs(std::remainder(a.theta - b.theta, 2 * M_PI)) <= options.orientation_tolerance;
}

}  // namespace

SearchNode StanceSearch::Run::make_node(int parent, const PostureRequest& request,
                                        const PostureResult& solved, const Stance& stance,
                                        const std::string& action,
                                        std::optional<Contact> changed) const {
  SearchNode node;
  node.id = int(tree_.size());
  node.parent = parent;
  node.depth = parent >= 0 ? tree_[size_t(parent)].depth + 1 : 0;
  for (const Contact& c : stance.contacts())
    for (size_t i = 0; i < request.contacts.size(); ++i)
      if (request.contacts[i].contact.same_surfaces(c))
        node.placements.push_back(solved.placements[i]);
  node.step = make_plan_step(request, solved, stance, action, changed);
  return node;
}

double StanceSearch::Run::milestone_tolerance(int m) const {
  const auto& given = problem_.milestone_tolerances;
  return m < int(given.size()) && given[size_t(m)] > 0.0 ? given[size_t(m)]
                                                         : options_.milestone_tolerance;
}

// The guide path ranks the nodes; the stance term only counts once the last milestone is the
// target (before that it would reward goal contacts made too early, e.g. hands on the desk while
// still walking to it).
double StanceSearch::Run::cost(const SearchNode& node) const {
  const double d = guide_.size() > 0 ? guide_.distance_to(node.q(), t_) : 0.0;
  const bool final_approach = t_ + 1 >= guide_.size();
  return d +
         (final_approach ? options_.stance_weight * stance_difference(node.stance(), goal_) : 0.0);
}

// The goal stance, at the goal's stated placements.
bool StanceSearch::Run::is_goal(const SearchNode& node) const {
  if (stance_difference(node.stance(), goal_) != 0) return false;
  for (const StanceContact& g : problem_.goal_stance) {
    if (!g.placement) continue;
    const int i = node.stance().find(g.contact);
    if (!same_placement(node.placements[size_t(i)], *g.placement, options_)) return false;
  }
  return true;
}

// Loop avoidance: the same stance at the same placements is already a node. A dropped node (its
// transition has no motion) only blocks the same transition, from the same parent: reached from
// another node, the stance is a new transition, which may have a motion.
bool StanceSearch::Run::in_tree(const Stance& stance, const std::vector<Placement>& placements,
                                int parent) const {
  for (const SearchNode& n : tree_) {
    if (!(n.stance() == stance) || (n.dropped && n.parent != parent)) continue;
    bool same = true;
    for (size_t i = 0; i < placements.size() && same; ++i)
      same = same_placement(n.placements[i], placements[i], options_);
    if (same) return true;
  }
  return false;
}

bool StanceSearch::Run::already_in_tree(const SearchNode& node) const {
  return in_tree(node.stance(), node.placements, node.parent);
}

// A removal keeps every other contact at its placement, so its child's stance and placements are
// known before the solve: when they are a node's, the solve would end "already in the tree"
// whatever its posture (removing the contact the node itself added gives back its parent).
bool StanceSearch::Run::removal_reaches_a_node(const SearchNode& node, const Candidate& c) const {
  if (c.add) return false;
  const Stance next = node.stance().without(node.stance().find(c.contact));
  return in_tree(next, child_placements(node, next, {}), node.id);  // a removal adds none
}

// An addition whose first attempt aims s1 (obj4's target, where s1 fits on s2 along the way:
// landing_estimate; or the goal's stated placement) within loop avoidance's tolerances of a node's
// placement of it, every other contact at that node's
// placements: the solve would most likely end "already in the tree" (the climb: putting back the
// sole just unloaded, aimed where it still stands). A prediction, not a proof (the solver may land
// elsewhere), so such a candidate waits for backtracking instead of being pruned.
bool StanceSearch::Run::addition_aims_at_a_node(const SearchNode& node, const Candidate& c) const {
  if (!c.add) return false;
  const AdditionAim aim = addition_aim(node, c.contact, 0);
  Placement landing = aim.placement
                          ? *aim.placement
                          : landing_estimate(problem_.scene, c.contact, aim.now, aim.target);
  // A point's angle is its link's turn about s2's normal, which nothing aims (a sphere turns
  // freely): the solve keeps about the node's.
  if (problem_.scene.surfaces.get(c.contact.s1).is_point()) landing.theta = aim.now.theta;
  const Stance next = node.stance().with(c.contact);
  return in_tree(next, child_placements(node, next, landing), node.id);
}

// The placements of a child `next` of `node` in its stance order, as make_node lists them: the
// node's for the contacts it keeps, `added` for the one it adds.
std::vector<Placement> StanceSearch::Run::child_placements(const SearchNode& node,
                                                           const Stance& next,
                                                           const Placement& added) const {
  std::vector<Placement> placements;
  for (const Contact& k : next.contacts()) {
    const int i = node.stance().find(k);
    placements.push_back(i >= 0 ? node.placements[size_t(i)] : added);
  }
  return placements;
}

// Fewest contacts from the goal's stance, then the lowest cost.
int StanceSearch::Run::closest() const {
  if (tree_.empty()) return -1;  // cancelled before the root was realised
  int best = 0;
  const auto key = [&](const SearchNode& x) {
    return std::make_pair(stance_difference(x.stance(), goal_), cost(x));
  };
  for (const SearchNode& n : tree_)
    if (!n.dropped && key(n) < key(tree_[size_t(best)])) best = n.id;
  return best;
}

// Milestone t is reached by a node within its tolerance, or by one that has gone past it: closer
// to milestone t + 1 than milestone t itself is (a stride that lands beyond a coarse guide's
// milestone leaves it behind; aimed at it still, the search would step back). Only between two
// milestones of one kind: t with no tolerance of its own (a stated one asks for precision), t and
// t + 1 stating the same entries and offering the same contacts (not past a heading, a posture
// or a phase).
bool StanceSearch::Run::reaches_milestone(const SearchNode& n, int t) const {
  if (guide_.distance_to(n.q(), t) <= milestone_tolerance(t)) return true;
  if (!options_.advance_past_milestones || t + 1 >= guide_.size()) return false;
  const auto& tolerances = problem_.milestone_tolerances;
  if (t < int(tolerances.size()) && tolerances[size_t(t)] > 0.0) return false;
  const auto offered = [&](int m) -> const auto& {  // options_for_milestone's, without a copy
    const auto& phases = problem_.milestone_contact_pairs;
    return m < int(phases.size()) && !phases[size_t(m)].empty() ? phases[size_t(m)]
                                                                : options_.contact_pairs;
  };
  if (!guide_.same_entries(t, t + 1) || offered(t) != offered(t + 1)) return false;
  return guide_.distance_to(n.q(), t + 1) < guide_.distance_to(guide_.milestone(t), t + 1);
}

// Advances t past every milestone the tree already reaches; publishes each.
void StanceSearch::Run::advance_milestones() {
  bool advanced = true;
  while (advanced && t_ + 1 < guide_.size()) {
    advanced = false;
    for (const SearchNode& n : tree_)
      if (!n.dropped && reaches_milestone(n, t_)) {
        ++t_;
        advanced = true;
        if (!search_.publish(node_event(SearchEventKind::Milestone, n, t_, int(tree_.size()))))
          return;
        break;
      }
  }
}

// Lazy expansion: a node that has had some of its candidates solved waits behind its children
// by as much as its next candidate is unlikely to carry its share (a knee on the floor 0.7 m from
// the guide's posture ranks the standing node 0.7 m lower), so a child that is nearly as close to
// the milestone is expanded first.
double StanceSearch::Run::priority(int n) const {
  const double c = cost(tree_[size_t(n)]);
  const bool partly_expanded =
      n < int(pending_.size()) && !pending_[size_t(n)].empty() && expanded_for_[size_t(n)] == t_;
  return partly_expanded ? c + std::max(0.0, pending_[size_t(n)].front().share) : c;
}

// The best open node (ties: the older node, for determinism), taken off the open list.
int StanceSearch::Run::pop_best_open() {
  const auto best = std::min_element(open_.begin(), open_.end(), [&](int a, int b) {
    const double ca = priority(a), cb = priority(b);
    return ca < cb || (ca == cb && a < b);
  });
  const int n = *best;
  open_.erase(best);
  return n;
}

}  // namespace stanceplan
