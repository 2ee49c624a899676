#include "planner/solver/hessian_cache.h"

namespace stanceplan {

std::shared_ptr<const HessianStructure> HessianCache::find(const Key& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : it->second;
}

void HessianCache::insert(const Key& key, std::shared_ptr<const HessianStructure> structure) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.size() >= kMaxEntries) entries_.clear();
  entries_.emplace(key, std::move(structure));
}

}  // namespace stanceplan
