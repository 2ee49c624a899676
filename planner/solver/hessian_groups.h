#pragma once
// Which configuration columns of the finite-difference Hessian (PostureNlp::hessian_values) can be
// perturbed together. Entities that share no contact task share no second derivative: a robot's
// configuration does not move the gradient rows of another robot it does not touch, nor the force
// rows of contacts it is not part of. So one gradient evaluation can difference a column of each
// of several entities at once when no two of them share a contact (a colouring of the contact
// graph): two robots carrying a table, two arms handing over a cylinder. A column then reads only
// the rows its own entity alone moves in that evaluation; an entry between two touching entities
// that neither column can read alone comes from the other column by symmetry. Single-entity
// systems keep one column per evaluation.
#include <cstdint>
#include <vector>

#include "planner/solver/nlp_layout.h"
#include "planner/solver/nlp_state.h"

namespace stanceplan {

struct HessianGroups {
  std::vector<std::vector<int>> groups;  // q columns differenced by one gradient evaluation
  std::vector<int> group_of_column;      // per q column
  std::vector<int> entity_of_column;     // per q column
  std::vector<uint64_t> group_entities;  // per group: bit e for each entity among its columns
  std::vector<uint64_t> row_entities;    // per row of the Hessian (n): entities whose q moves it

  bool shared(int column) const {
    return groups[size_t(group_of_column[size_t(column)])].size() > 1;
  }
  // The row does not depend on the column's entity: the entry is zero.
  bool structural_zero(int row, int column) const {
    return (row_entities[size_t(row)] & bit(entity_of_column[size_t(column)])) == 0;
  }
  // The column's evaluation moved the row through the column's entity alone.
  bool readable(int row, int column) const {
    const uint64_t mine = bit(entity_of_column[size_t(column)]);
    return !shared(column) || (row_entities[size_t(row)] &
                               group_entities[size_t(group_of_column[size_t(column)])]) == mine;
  }
  static uint64_t bit(int entity) { return uint64_t{1} << entity; }
};

// Greedy colouring of the entities with configuration in entity order (deterministic). Falls back
// to one column per group when a needed entry could be read from neither side, or with more than
// 64 entities.
HessianGroups make_hessian_groups(const System& system,
                                  const std::vector<ContactConstants>& contacts,
                                  const NlpLayout& layout);

}  // namespace stanceplan
