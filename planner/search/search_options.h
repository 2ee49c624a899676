#pragma once
// Budgets and tolerances of the stance search (docs/METHOD.md section 3), read from a scenario's
// `search` section and overridable on the command line.
#include <string>
#include <utility>
#include <vector>

namespace stanceplan {

struct SearchOptions {
  int max_nodes = 2000;  // nodes expanded before giving up
  // Wall-clock budget of the search: neither the time the step gate holds it nor the transition
  // checks' (stance_search.h) count.
  double time_limit_s = 60.0;
  double milestone_tolerance = 0.15;  // distance at which a milestone counts as reached
  // A milestone also counts as reached by a node closer to the next milestone than it is itself.
  bool advance_past_milestones = true;
  int threads = 0;  // candidate solves in parallel; 0 = the number of cores
  // Pruning (candidates.h): surfaces farther apart than this are not offered as a new contact;
  // contacts between two surfaces of one entity only when self_contacts is true.
  double contact_reach = 0.45;
  bool self_contacts = false;
  // A contact is not removed when a floating body with mass would keep fewer contacts than this:
  // 1 is exact (no equilibrium without support); more is an option (a hand that keeps three
  // fingertips on a ball).
  int min_contacts = 1;
  // When not empty, only these surface pairs are offered as new contacts: ("s1 id", "s2 id"),
  // each a pattern where * matches any run of characters ("robot/*_sole", "env/floor").
  std::vector<std::pair<std::string, std::string>> contact_pairs;
  // Contacts (same patterns) offered only once every other goal contact is in the stance: e.g.
  // forearms on a desk, which pin the upper body and would keep the robot from sitting down.
  std::vector<std::pair<std::string, std::string>> last_contacts;
  // Loop avoidance: a stance is already in the tree when it has the same contacts at placements
  // within these tolerances.
  double placement_tolerance = 0.03;    // m
  double orientation_tolerance = 0.15;  // rad
  // Cost: distance to the targeted milestone, plus stance_weight x |stance xor goal stance| once
  // the last milestone is the target.
  double stance_weight = 0.1;
  // Backtracking: further attempts from other initial guesses per failed (node, candidate); none
  // after a first solve that ended infeasible (StanceSearch::Run::worth_retrying).
  int max_retries = 2;
  // A candidate that failed its first attempt from the same stance, posture and relative placement
  // of its surfaces is deferred to backtracking instead of being solved at once (failure_memo.h; a
  // heuristic: it orders, never prunes). So are, once an addition failed from a node, that node's
  // other additions of a surface of the same link on the same partner (other facets of one body:
  // the untuned dual-arm hand-over 115 -> 103 calls, no other scenario changed), and a lazy batch
  // takes one such addition at a time, the others waiting for its outcome (103 -> 61, the 22 other
  // untuned, paper and guide-free runs unchanged).
  bool defer_repeated_failures = true;
  // An addition whose first attempt aims its surface at a node's placement of it, the other
  // contacts at that node's placements (putting back the sole just unloaded, aimed where it still
  // stands), is deferred to backtracking: its solve would most likely end "already in the tree"
  // (StanceSearch::Run::addition_aims_at_a_node; a heuristic: it orders, never prunes).
  bool defer_predicted_loops = true;
  // A removal after which a held rigid object (an object entity without joints) cannot balance on
  // its other contacts' friction cones at the node's configuration (object_balance.h: a pad left
  // alone on a standing cylinder's side) is deferred to backtracking (a heuristic: the solve may
  // turn the object; it orders, never prunes). Off: on eight shifted starts each, one scenario
  // gained a plan and two lost one (README, Untuned scenarios, session 20).
  bool defer_unbalanced_removals = false;
  // When every stance was tried and no node came within tolerance of the targeted milestone, the
  // search aims at the next one instead of giving up (every node is expanded again for it; a
  // Milestone event with a message says which was skipped). The guide is a heuristic: a milestone
  // sampled between two phases (a crouch over a seat with the soles only, before the thighs are
  // offered) may have no balanced posture near it. The last milestone is never skipped.
  bool skip_unreached_milestones = true;
  // Lazy expansion: a node's candidates are solved this many at a time, in order; the node stays
  // open with the rest, ranked by its cost plus its next candidate's support share, so the search
  // moves on as soon as a child is better than it. 0 solves every candidate of an expansion at
  // once (Algorithm 1 as written). Measured with bench/untuned_bench (README, Untuned scenarios):
  // 3 (the default) takes none of the paper's scenarios to more calls than 0 (desk 91 -> 84, ball
  // 187 -> 141, dual arm 66 -> 40, ...) and the untuned ones to fewer or as many (stairs 77 -> 38,
  // dual-arm hand-over 348 -> 114, side-step 20 -> 18, walk with a turn 29); 2 makes fewer calls
  // on the untuned ones (31, 82, 17, 28) but more on the paper's dual arm (71). The paper's dual
  // arm's hand-over with 3 moves at every step (its step 10 once had no motion, before the motion's
  // secant predictor). Never tied to `threads`: the plan is the same with any number of solver
  // processes.
  int expansion_batch = 3;
  // With lazy expansion and ordered candidates, a node's first candidate is solved alone when the
  // guide's posture realises it (support share <= batch_margin, m) and every other is an addition
  // whose share is more than batch_margin larger; those are deferred to backtracking (tried once
  // no node is open). A heuristic: it orders, never prunes. Measured (bench/untuned_bench,
  // scenario_bench, README): stairs 38 -> 24 calls, side-step 18 -> 16, ball 141 -> 112, pen
  // 92 -> 74, none more; 0.05 took the ball to 194, 0.1 the stairs back to 34. Negative: batches of
  // expansion_batch whatever the shares.
  double batch_margin = 0.03;
  // With lazy expansion, the order of a node's candidates: removals, then additions by how close
  // the guide's posture is to realising them (support_share.h; a heuristic); false: the
  // enumeration's order.
  bool order_candidates = true;
  // Candidate solves that make no progress stop early: each gets this many Ipopt iterations, and
  // 20 more whenever its constraint violation falls tenfold (StallRule::budget,
  // planner/solver/stall_monitor.h; a heuristic: a stopped solve is a rejection, never lets
  // anything through). With lazy expansion (2 or 3) 30 stopped no solve that would have succeeded
  // on the untuned and the paper's scenarios (the same calls and plans, 20-55 % fewer
  // iterations); with expansion_batch 0 it stops slow successes of the untuned dual-arm hand-over
  // (348 -> 796 calls): set it to 0 with expansion_batch 0. 0: every candidate runs to the
  // solver's iteration limit.
  int progress_budget = 30;
};

}  // namespace stanceplan
