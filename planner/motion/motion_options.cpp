#include "planner/motion/motion_options.h"

#include <cmath>
#include <cstdio>

namespace stanceplan {

std::string check_motion_options(const MotionOptions& o) {
  const auto found = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return std::string(text);
  };
  if (!(o.point_spacing > 0.0) || !std::isfinite(o.point_spacing))
    return "point_spacing: expected a number > 0 (m), found " + found(o.point_spacing);
  if (!(o.joint_spacing > 0.0) || !std::isfinite(o.joint_spacing))
    return "joint_spacing: expected a number > 0 (rad), found " + found(o.joint_spacing);
  if (!(o.clearance >= 0.0) || !std::isfinite(o.clearance))
    return "clearance: expected a number >= 0 (m), found " + found(o.clearance);
  if (!(o.reference_weight > 0.0) || !std::isfinite(o.reference_weight))
    return "reference_weight: expected a number > 0, found " + found(o.reference_weight);
  if (o.max_halvings < 0 || o.max_halvings > 30)
    return "max_halvings: expected 0..30, found " + std::to_string(o.max_halvings);
  if (o.max_samples < 1)
    return "max_samples: expected >= 1, found " + std::to_string(o.max_samples);
  if (o.max_solves < 1) return "max_solves: expected >= 1, found " + std::to_string(o.max_solves);
  const StanceRrtOptions& d = o.detour;
  if (d.max_projections < 0)
    return "detour.max_projections: expected >= 0, found " + std::to_string(d.max_projections);
  if (!(d.spread >= 0.0) || !std::isfinite(d.spread))
    return "detour.spread: expected a number >= 0 (rad), found " + found(d.spread);
  if (!(d.step > 0.0 && d.step <= 1.0))
    return "detour.step: expected a number in (0, 1], found " + found(d.step);
  if (d.max_connect_steps < 1)
    return "detour.max_connect_steps: expected >= 1, found " + std::to_string(d.max_connect_steps);
  if (d.shortcut_attempts < 0)
    return "detour.shortcut_attempts: expected >= 0, found " + std::to_string(d.shortcut_attempts);
  if (d.max_shortcut_projections < 0)
    return "detour.max_shortcut_projections: expected >= 0, found " +
           std::to_string(d.max_shortcut_projections);
  return "";
}

}  // namespace stanceplan
