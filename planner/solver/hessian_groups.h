#pragma once
// Which configuration columns of the finite-difference Hessian (PostureNlp::hessian_values) can be
// perturbed together, and which entries can be nonzero at all.
//
// Most second derivatives of the program are structurally zero: a joint of the left arm and a
// joint of the right leg share no term (every constraint row and objective term is a sum of
// per-link terms, each a function of the joints on that link's path to the root; collision rows
// get no curvature), nor do two robots that do not touch. `pattern` records, for every q column k,
// which rows of the Lagrangian's gradient move when q_k moves; PostureNlp measures it once per
// program (a gradient evaluation per column at a generic point: a row that does not read q_k
// comes out bit for bit the same). Columns whose moved rows do not overlap are then differenced
// by one gradient evaluation (a colouring, as in Curtis, Powell & Reid 1974 and its symmetric
// variant by Coleman & Moré 1984): an entry is read from its column when no other column of the
// group moves its row, or else, in the q-q block, from its mirror entry. Ipopt is told only the
// entries the pattern allows, which keeps its KKT matrix sparse.
#include <cstddef>
#include <vector>

namespace stanceplan {

struct HessianGroups {
  int n = 0;                             // rows: all variables (q, lambda)
  int nq = 0;                            // differenced columns: q
  std::vector<char> pattern;             // n x nq, column-major; q-q part symmetric, diagonal set
  std::vector<std::vector<int>> groups;  // q columns differenced by one gradient evaluation
  std::vector<int> group_of_column;      // per q column
  std::vector<int> count;                // groups x n: columns of the group that move the row

  bool nonzero(int row, int column) const {
    return pattern[std::size_t(column) * std::size_t(n) + std::size_t(row)] != 0;
  }
  // The column's evaluation moved the row through that column alone.
  bool readable(int row, int column) const {
    return nonzero(row, column) &&
           count[std::size_t(group_of_column[std::size_t(column)]) * std::size_t(n) +
                 std::size_t(row)] == 1;
  }
  // Entry (i, j) of the Hessian (i >= j, j < nq) can be nonzero.
  bool needed(int i, int j) const { return nonzero(i, j) || (i < nq && nonzero(j, i)); }
};

// Greedy colouring in column order (deterministic). `pattern` (n x nq, column-major) is made
// symmetric in its q-q part and given its diagonal. Every entry the pattern allows is readable
// from its column, or (q-q) from its mirror's.
HessianGroups make_hessian_groups(std::vector<char> pattern, int n, int nq);

}  // namespace stanceplan
