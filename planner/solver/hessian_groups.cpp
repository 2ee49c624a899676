#include "planner/solver/hessian_groups.h"

namespace stanceplan {

namespace {

class Colouring {
 public:
  explicit Colouring(HessianGroups& g) : g_(g) {}

  void assign(int k) {
    for (int G = 0; G < int(g_.groups.size()); ++G)
      if (try_add(k, G)) return;
    // A group of its own: every row it moves is read from it alone.
    g_.group_of_column[std::size_t(k)] = int(g_.groups.size());
    g_.groups.push_back({k});
    g_.count.resize(g_.count.size() + std::size_t(g_.n), 0);
    move(k, int(g_.groups.size()) - 1, +1);
  }

 private:
  int& count(int G, int row) {
    return g_.count[std::size_t(G) * std::size_t(g_.n) + std::size_t(row)];
  }

  void move(int k, int G, int delta) {
    for (int i = 0; i < g_.n; ++i)
      if (g_.nonzero(i, k)) count(G, i) += delta;
  }

  // Columns not yet coloured count as alone in their group.
  bool readable(int row, int column) const {
    if (g_.group_of_column[std::size_t(column)] < 0) return g_.nonzero(row, column);
    return g_.readable(row, column);
  }
  bool recoverable(int row, int column) const {
    return readable(row, column) || (row < g_.nq && readable(column, row));
  }

  bool try_add(int k, int G) {
    g_.group_of_column[std::size_t(k)] = G;
    move(k, G, +1);
    g_.groups[std::size_t(G)].push_back(k);
    if (consistent(k, G)) return true;
    g_.groups[std::size_t(G)].pop_back();
    move(k, G, -1);
    g_.group_of_column[std::size_t(k)] = -1;
    return false;
  }

  // Adding k to G only changes what G's columns read in the rows k moves.
  bool consistent(int k, int G) {
    for (int i = 0; i < g_.n; ++i) {
      if (!g_.nonzero(i, k) || count(G, i) < 2) continue;
      for (int c : g_.groups[std::size_t(G)])
        if (g_.nonzero(i, c) && !recoverable(i, c)) return false;
    }
    return true;
  }

  HessianGroups& g_;
};

}  // namespace

HessianGroups make_hessian_groups(std::vector<char> pattern, int n, int nq) {
  HessianGroups g;
  g.n = n;
  g.nq = nq;
  g.pattern = std::move(pattern);
  auto at = [&](int i, int k) -> char& {
    return g.pattern[std::size_t(k) * std::size_t(n) + std::size_t(i)];
  };
  for (int k = 0; k < nq; ++k) {
    at(k, k) = 1;
    for (int i = 0; i < k; ++i)
      if (at(i, k) || at(k, i)) at(i, k) = at(k, i) = 1;
  }
  g.group_of_column.assign(std::size_t(nq), -1);
  Colouring colouring(g);
  for (int k = 0; k < nq; ++k) colouring.assign(k);
  return g;
}

}  // namespace stanceplan
