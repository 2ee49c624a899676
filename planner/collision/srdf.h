#pragma once
// The part of an SRDF file (MoveIt's Semantic Robot Description Format) the collision model uses:
// the link pairs whose collisions are disabled, <disable_collisions link1="" link2="" reason=""/>.
#include <string>
#include <vector>

namespace stanceplan {

struct DisabledCollision {
  std::string link1;
  std::string link2;
  std::string reason;  // "Adjacent", "Never", ... (informative only; may be empty)
};

// Throws InputError naming the file (and the line when known) on a missing file, malformed XML,
// a root element other than <robot>, or a <disable_collisions> without link1/link2.
std::vector<DisabledCollision> load_srdf_disabled_collisions(const std::string& path);
// Same, from XML text; display_name stands for the file name in messages.
std::vector<DisabledCollision> parse_srdf_disabled_collisions(
    const std::string& xml, const std::string& display_name = "<string>");

}  // namespace stanceplan
