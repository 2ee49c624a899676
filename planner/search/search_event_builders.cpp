#include "planner/search/search_event_builders.h"

#include <memory>

namespace stanceplan {

// A node's event carries the stance as the node realised it: the contacts with the ones that
// carry force, the forces, torques and the solve's iterations (milestone, goal and expansion
// events show the node's loaded contacts, as the candidate that made it did).
SearchEvent node_event(SearchEventKind kind, const SearchNode& node, int milestone, int nodes) {
  SearchEvent e;
  e.kind = kind;
  e.node = node.id;
  e.stance = node.stance();
  e.q = node.q();
  e.contacts = node.step.contacts;
  e.forces = node.step.forces;
  e.iterations = node.step.iterations;
  e.torques = node.step.torques;
  e.milestone = milestone;
  e.nodes = nodes;
  return e;
}

SearchEvent expansion_event(const SearchNode& node, int milestone, int nodes) {
  return node_event(SearchEventKind::Expansion, node, milestone, nodes);
}

SearchEvent root_event(const SearchNode& root, const PostureResult& solved) {
  SearchEvent e;
  e.kind = SearchEventKind::Candidate;
  e.node = root.id;
  e.stance = root.stance();
  e.accepted = true;
  e.q = root.q();
  e.contacts = root.step.contacts;
  e.forces = root.step.forces;
  e.time_ms = solved.time_ms;
  e.iterations = solved.iterations;
  e.torques = solved.torques;
  e.residuals = solved.residuals;
  e.nodes = 1;
  return e;
}

SearchEvent candidate_event(int parent, const Stance& stance, bool add, const Contact& changed,
                            const PostureRequest& request, const PostureResult& solved) {
  SearchEvent e;
  e.kind = SearchEventKind::Candidate;
  e.parent = parent;
  e.stance = stance;
  e.candidate_case = add ? CandidateCase::Add : CandidateCase::Remove;
  e.changed = changed;
  e.status = solved.status;
  e.message = solved.message;
  e.q = solved.q;
  for (const ContactTask& task : request.contacts)
    e.contacts.push_back({task.contact, task.loaded});
  e.forces = solved.forces;
  e.time_ms = solved.time_ms;
  e.iterations = solved.iterations;
  e.torques = solved.torques;
  e.residuals = solved.residuals;
  e.request = std::make_shared<const PostureRequest>(request);
  return e;
}

SearchEvent failure_event(const std::string& message, const std::vector<SearchNode>& tree,
                          int closest) {
  SearchEvent e;
  e.kind = SearchEventKind::Failure;
  e.message = message;
  e.node = closest;
  e.nodes = int(tree.size());
  if (closest >= 0) e.stance = tree[size_t(closest)].stance();
  return e;
}

}  // namespace stanceplan
