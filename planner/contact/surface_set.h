#pragma once
// Every contact surface of a system, per entity, addressed by SurfaceRef or by the id
// "entity/surface" that scenario and plan files use.
#include <optional>
#include <string>
#include <vector>

#include "planner/contact/surface.h"
#include "planner/model/system.h"

namespace stanceplan {

struct SurfaceRef {
  int entity = -1;
  int index = -1;  // into SurfaceSet::of(entity)
  auto operator<=>(const SurfaceRef&) const = default;
};

class SurfaceSet {
 public:
  SurfaceSet() = default;
  explicit SurfaceSet(int num_entities) : surfaces_(num_entities) {}

  void set(int entity, std::vector<Surface> surfaces) {
    surfaces_.at(entity) = std::move(surfaces);
  }
  const std::vector<Surface>& of(int entity) const { return surfaces_.at(entity); }
  const Surface& get(SurfaceRef ref) const { return surfaces_.at(ref.entity).at(ref.index); }
  int num_entities() const { return static_cast<int>(surfaces_.size()); }

  // "entity/surface" -> reference; nullopt when either part is unknown.
  std::optional<SurfaceRef> find(const System& system, const std::string& id) const;
  std::string id(const System& system, SurfaceRef ref) const;

 private:
  std::vector<std::vector<Surface>> surfaces_;
};

}  // namespace stanceplan
