#include "planner/solver/hessian_groups.h"

#include <algorithm>

namespace stanceplan {

namespace {

// One column per group, every row readable: the plain forward difference.
HessianGroups singletons(HessianGroups g, int nq) {
  g.groups.clear();
  g.group_entities.clear();
  for (int c = 0; c < nq; ++c) {
    g.groups.push_back({c});
    g.group_of_column[size_t(c)] = c;
    g.group_entities.push_back(HessianGroups::bit(g.entity_of_column[size_t(c)]));
  }
  return g;
}

// Every entry the Hessian needs (lower triangle, configuration columns) is a structural zero or
// readable from its column, or (configuration rows) from its row's column.
bool complete(const HessianGroups& g, int nq, int n) {
  for (int j = 0; j < nq; ++j)
    for (int i = j; i < n; ++i) {
      if (g.structural_zero(i, j) || g.readable(i, j)) continue;
      if (i < nq && (g.structural_zero(j, i) || g.readable(j, i))) continue;
      return false;
    }
  return true;
}

}  // namespace

HessianGroups make_hessian_groups(const System& system,
                                  const std::vector<ContactConstants>& contacts,
                                  const NlpLayout& layout) {
  const int entities = system.num_entities();
  const int nq = layout.nq;
  HessianGroups g;
  g.group_of_column.assign(size_t(nq), -1);
  g.entity_of_column.assign(size_t(nq), -1);
  for (int e = 0; e < entities; ++e)
    for (int k = 0; k < system.entity(e).nq(); ++k)
      g.entity_of_column[size_t(system.offset(e) + k)] = e;
  if (entities > 64) return singletons(g, nq);
  // The contact graph: every task (loaded or not) ties its two entities through its geometry rows.
  std::vector<uint64_t> touching(size_t(entities), 0);
  for (const ContactConstants& c : contacts) {
    touching[size_t(c.e1)] |= HessianGroups::bit(c.e2);
    touching[size_t(c.e2)] |= HessianGroups::bit(c.e1);
  }
  g.row_entities.assign(size_t(layout.n), 0);
  for (int c = 0; c < nq; ++c) {
    const int e = g.entity_of_column[size_t(c)];
    g.row_entities[size_t(c)] = HessianGroups::bit(e) | touching[size_t(e)];
  }
  for (const ForceBlock& block : layout.forces) {
    const ContactConstants& c = contacts[size_t(block.task)];
    for (int i = 0; i < block.size(); ++i)
      g.row_entities[size_t(block.first_column + i)] =
          HessianGroups::bit(c.e1) | HessianGroups::bit(c.e2);
  }
  // Greedy colouring of the entities that have a configuration.
  std::vector<uint64_t> colours;
  std::vector<std::vector<int>> members;
  for (int e = 0; e < entities; ++e) {
    if (system.entity(e).nq() == 0) continue;
    size_t k = 0;
    while (k < colours.size() && (colours[k] & (touching[size_t(e)] | HessianGroups::bit(e)))) ++k;
    if (k == colours.size()) {
      colours.push_back(0);
      members.emplace_back();
    }
    colours[k] |= HessianGroups::bit(e);
    members[k].push_back(e);
  }
  for (size_t k = 0; k < members.size(); ++k) {
    int slots = 0;
    for (int e : members[k]) slots = std::max(slots, system.entity(e).nq());
    for (int s = 0; s < slots; ++s) {
      std::vector<int> group;
      for (int e : members[k])
        if (s < system.entity(e).nq()) group.push_back(system.offset(e) + s);
      uint64_t perturbed = 0;
      for (int c : group) {
        g.group_of_column[size_t(c)] = int(g.groups.size());
        perturbed |= HessianGroups::bit(g.entity_of_column[size_t(c)]);
      }
      g.group_entities.push_back(perturbed);
      g.groups.push_back(std::move(group));
    }
  }
  if (!complete(g, nq, layout.n)) return singletons(g, nq);
  return g;
}

}  // namespace stanceplan
