#include "planner/model/entity.h"

namespace stanceplan {

const char* to_string(EntityKind kind) {
  switch (kind) {
    case EntityKind::Environment:
      return "environment";
    case EntityKind::FixedRobot:
      return "fixed";
    case EntityKind::FloatingRobot:
      return "floating";
    case EntityKind::Object:
      return "object";
  }
  return "?";
}

bool parse_entity_kind(const std::string& text, EntityKind* kind) {
  for (EntityKind k : {EntityKind::Environment, EntityKind::FixedRobot, EntityKind::FloatingRobot,
                       EntityKind::Object}) {
    if (text == to_string(k)) {
      *kind = k;
      return true;
    }
  }
  return false;
}

}  // namespace stanceplan
