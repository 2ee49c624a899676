#pragma once
// A value computed once per unordered pair of surfaces of one entity (the search's per-model
// bounds: normal_angle_range.h, reach_bound.h), keyed by (entity, lower index, higher index).
#include <map>
#include <tuple>
#include <utility>

#include "planner/scene/scene.h"

namespace stanceplan {

template <class Value>
class SurfacePairCache {
 public:
  // The cached value of {a, b} (either order), computed by compute(a, b) on first use with a's
  // index the lower one.
  template <class Compute>
  const Value& get(SurfaceRef a, SurfaceRef b, Compute&& compute) {
    if (b.index < a.index) std::swap(a, b);
    const auto key = std::make_tuple(a.entity, a.index, b.index);
    auto it = values_.find(key);
    if (it != values_.end()) return it->second;
    return values_.emplace(key, compute(a, b)).first->second;
  }

 private:
  std::map<std::tuple<int, int, int>, Value> values_;
};

}  // namespace stanceplan
