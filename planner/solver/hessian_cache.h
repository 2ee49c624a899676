#pragma once
// The finite-difference Hessian's structure (which entries can be nonzero, which columns share an
// evaluation: hessian_groups.h) depends only on the program's shape — which contacts, loaded or
// not, fixed or free, and which constraint families — not on the request's values, because it is
// measured at a canonical point (PostureNlp::probe_point). Measuring it costs one gradient
// evaluation per configuration column; the search asks for the same few shapes over and over, so
// PostureSolver keeps them here. Thread-safe.
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "planner/solver/hessian_groups.h"

namespace stanceplan {

struct HessianStructure {
  // Where an entry's value comes from: the differenced column j (H(i, j)), the mirror column i
  // (H(j, i), q-q block), the mean of both, or the exact lambda-lambda block.
  enum class Source : char { Column, Mirror, Mean, Exact };
  HessianGroups groups;
  std::vector<int> rows, cols;  // the entries given to the solver (lower triangle)
  std::vector<Source> sources;  // per entry
};

class HessianCache {
 public:
  using Key = std::vector<int>;
  std::shared_ptr<const HessianStructure> find(const Key& key) const;
  void insert(const Key& key, std::shared_ptr<const HessianStructure> structure);

 private:
  static constexpr size_t kMaxEntries =
      512;  // a search meets tens of shapes; this only bounds memory
  mutable std::mutex mutex_;
  std::map<Key, std::shared_ptr<const HessianStructure>> entries_;
};

}  // namespace stanceplan
