#include "render/scene/ground.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace stanceplan::render {
namespace {

struct Rect {
  Eigen::Vector2d min, max;
};

bool is_slab(const Eigen::AlignedBox3d& box, double slab_ratio) {
  const Eigen::Vector3d size = box.sizes();
  return size.z() <= slab_ratio * std::min(size.x(), size.y());
}

// Is `area` inside the union of `tiles`? Exact: the tiles' edges cut the area into cells, and
// every cell's centre must lie in a tile.
bool covered(const Rect& area, const std::vector<Rect>& tiles) {
  std::vector<double> xs = {area.min.x(), area.max.x()}, ys = {area.min.y(), area.max.y()};
  for (const Rect& t : tiles) {
    for (double x : {t.min.x(), t.max.x()})
      if (x > area.min.x() && x < area.max.x()) xs.push_back(x);
    for (double y : {t.min.y(), t.max.y()})
      if (y > area.min.y() && y < area.max.y()) ys.push_back(y);
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  for (size_t i = 0; i + 1 < xs.size(); ++i) {
    for (size_t j = 0; j + 1 < ys.size(); ++j) {
      const Eigen::Vector2d c(0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1]));
      const bool inside = std::any_of(tiles.begin(), tiles.end(), [&](const Rect& t) {
        return (c.array() >= t.min.array()).all() && (c.array() <= t.max.array()).all();
      });
      if (!inside) return false;
    }
  }
  return true;
}

// The subject's footprint grown by the margin; the whole scene's when there is no subject.
Rect footprint(const DrawList& list, double margin) {
  const Eigen::AlignedBox3d subject = list.bounds(false);
  const Eigen::AlignedBox3d box = subject.isEmpty() ? list.bounds(true) : subject;
  const double grow = subject.isEmpty() ? 0.0 : margin;
  return {box.min().head<2>().array() - grow, box.max().head<2>().array() + grow};
}

}  // namespace

Ground find_ground(const DrawList& list, const GroundRule& rule) {
  std::vector<Eigen::AlignedBox3d> boxes;
  std::vector<bool> slab;
  double lowest = std::numeric_limits<double>::infinity();
  double floor_top = std::numeric_limits<double>::infinity();
  for (const DrawItem& item : list.items) {
    const Eigen::AlignedBox3d box = item.world_bounds();
    if (box.isEmpty()) continue;
    boxes.push_back(box);
    slab.push_back(item.environment && is_slab(box, rule.slab_ratio));
    lowest = std::min(lowest, box.min().z());
    if (slab.back()) floor_top = std::min(floor_top, box.max().z());
  }
  if (boxes.empty()) return Ground{};
  const Ground plane{std::min(0.0, lowest), false};
  if (!std::isfinite(floor_top)) return plane;
  // The floor: the slabs whose tops are at floor_top. Everything else must stand on or above it.
  std::vector<Rect> tiles;
  for (size_t i = 0; i < boxes.size(); ++i) {
    if (slab[i] && boxes[i].max().z() <= floor_top + rule.top_tolerance) {
      tiles.push_back({boxes[i].min().head<2>(), boxes[i].max().head<2>()});
    } else if (boxes[i].min().z() < floor_top - rule.sink_tolerance) {
      return plane;
    }
  }
  if (!covered(footprint(list, rule.margin), tiles)) return plane;
  return Ground{floor_top, true};
}

}  // namespace stanceplan::render
