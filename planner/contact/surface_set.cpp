#include "planner/contact/surface_set.h"

namespace stanceplan {

std::optional<SurfaceRef> SurfaceSet::find(const System& system, const std::string& id) const {
  const size_t slash = id.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const int entity = system.find_entity(id.substr(0, slash));
  if (entity < 0 || entity >= num_entities()) return std::nullopt;
  const std::string name = id.substr(slash + 1);
  const auto& list = surfaces_[entity];
  for (int i = 0; i < static_cast<int>(list.size()); ++i)
    if (list[i].name == name) return SurfaceRef{entity, i};
  return std::nullopt;
}

std::string SurfaceSet::id(const System& system, SurfaceRef ref) const {
  return system.entity(ref.entity).name + "/" + get(ref).name;
}

}  // namespace stanceplan
