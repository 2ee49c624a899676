#include "planner/contact/convex_partition.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planner/contact/polygon.h"

namespace stanceplan {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Distance of p from the line through a and b (from a when they coincide).
double distance_to_line(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length = ab.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(cross2(ab, p - a)) / length;
}

// Where the ray from `origin` along `direction` first meets an edge of `polygon` from the inside
// (the polygon's interior is left of each edge), skipping the edges at vertex `skip`. Returns the
// edge index k (edge k -> k + 1) or -1, and the point in *hit.
int first_hit(const Polygon2& polygon, int skip, const Eigen::Vector2d& origin,
              const Eigen::Vector2d& direction, Eigen::Vector2d* hit) {
  const int n = static_cast<int>(polygon.size());
  int best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    if (k == skip || (k + 1) % n == skip) continue;
    const Eigen::Vector2d& a = polygon[k];
    const Eigen::Vector2d edge = polygon[(k + 1) % n] - a;
    const double denominator = cross2(direction, edge);
    // Only edges the ray leaves the interior through: the direction points to their right.
    if (!(cross2(edge, direction) < 0.0)) continue;
    const Eigen::Vector2d w = a - origin;
    const double t = cross2(w, edge) / denominator;
    const double u = cross2(w, direction) / denominator;
    if (t <= 1e-9 || u < -1e-12 || u > 1.0 + 1e-12 || t >= best_t) continue;
    best_t = t;
    best = k;
  }
  if (best >= 0) *hit = origin + best_t * direction;
  return best;
}

// Vertices from index `from` to index `to` (inclusive), going forward around the polygon.
Polygon2 chain(const Polygon2& polygon, int from, int to) {
  const int n = static_cast<int>(polygon.size());
  Polygon2 out;
  for (int i = from;; i = (i + 1) % n) {
    out.push_back(polygon[i]);
    if (i == to) break;
  }
  return out;
}

// The hole joined to `outer` by a two-way bridge from its rightmost vertex along +x to the nearest
// boundary point P: outer up to P, the hole from that vertex round to it again, P, the rest.
Polygon2 bridge_hole(const Polygon2& outer, const Polygon2& hole) {
  int m = 0;
  for (int i = 1; i < static_cast<int>(hole.size()); ++i)
    if (hole[i].x() > hole[m].x() || (hole[i].x() == hole[m].x() && hole[i].y() < hole[m].y()))
      m = i;
  Eigen::Vector2d p;
  const int k = first_hit(outer, -1, hole[m], Eigen::Vector2d::UnitX(), &p);
  if (k < 0) return outer;  // not inside: a region's hole always is
  Polygon2 out(outer.begin(), outer.begin() + k + 1);
  out.push_back(p);
  for (size_t i = 0; i <= hole.size(); ++i) out.push_back(hole[(m + i) % hole.size()]);
  out.push_back(p);
  out.insert(out.end(), outer.begin() + k + 1, outer.end());
  return out;
}

// Index of the first reflex vertex (a right turn), or -1 when the polygon is convex.
int first_reflex(const Polygon2& polygon) {
  const int n = static_cast<int>(polygon.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& prev = polygon[(i + n - 1) % n];
    const Eigen::Vector2d& next = polygon[(i + 1) % n];
    if (cross2(polygon[i] - prev, next - polygon[i]) < 0.0) return i;
  }
  return -1;
}

}  // namespace

double signed_area2(const Polygon2& polygon) {
  double a = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i)
    a += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return a;
}

Polygon2 simplify_polygon(const Polygon2& polygon, double tolerance) {
  Polygon2 p = polygon;
  bool changed = true;
  while (changed && p.size() >= 3) {
    changed = false;
    Polygon2 kept;
    const size_t n = p.size();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d& prev = kept.empty() ? p[n - 1] : kept.back();
      const Eigen::Vector2d& next = p[(i + 1) % n];
      if ((p[i] - prev).norm() <= 1e-12 || distance_to_line(p[i], prev, next) <= tolerance) {
        changed = true;
        continue;
      }
      kept.push_back(p[i]);
    }
    p = std::move(kept);
  }
  if (p.size() < 3) p.clear();
  return p;
}

std::vector<Polygon2> convex_partition(const Polygon2& outer, const std::vector<Polygon2>& holes,
                                       double tolerance) {
  Polygon2 joined = simplify_polygon(outer, tolerance);
  if (joined.empty()) return {};
  std::vector<Polygon2> simple_holes;
  for (const Polygon2& h : holes)
    if (Polygon2 s = simplify_polygon(h, tolerance); !s.empty()) simple_holes.push_back(s);
  auto max_x = [](const Polygon2& p) {
    double m = -std::numeric_limits<double>::infinity();
    for (const auto& v : p) m = std::max(m, v.x());
    return m;
  };
  std::stable_sort(simple_holes.begin(), simple_holes.end(),
                   [&](const Polygon2& a, const Polygon2& b) { return max_x(a) > max_x(b); });
  for (const Polygon2& h : simple_holes) joined = bridge_hole(joined, h);

  std::vector<Polygon2> pieces, work = {joined};
  // Each cut removes a reflex vertex; the bound only guards against a malformed boundary.
  int budget = 4 * static_cast<int>(joined.size()) + 16;
  while (!work.empty() && budget-- > 0) {
    Polygon2 p = simplify_polygon(work.back(), tolerance);
    work.pop_back();
    if (p.empty()) continue;
    const int i = first_reflex(p);
    if (i < 0) {
      pieces.push_back(std::move(p));
      continue;
    }
    const int n = static_cast<int>(p.size());
    const Eigen::Vector2d& v = p[i];
    Eigen::Vector2d hit_in, hit_out;
    const int k_in = first_hit(p, i, v, (v - p[(i + n - 1) % n]).normalized(), &hit_in);
    const int k_out = first_hit(p, i, v, (v - p[(i + 1) % n]).normalized(), &hit_out);
    if (k_in < 0 && k_out < 0) continue;  // a malformed (self-crossing) boundary: dropped
    const bool use_in = k_out < 0 || (k_in >= 0 && (hit_in - v).norm() <= (hit_out - v).norm());
    const int k = use_in ? k_in : k_out;
    const Eigen::Vector2d hit = use_in ? hit_in : hit_out;
    Polygon2 a = chain(p, i, k);
    a.push_back(hit);
    Polygon2 b = {hit};
    const Polygon2 rest = chain(p, (k + 1) % n, i);
    b.insert(b.end(), rest.begin(), rest.end());
    work.push_back(std::move(b));
    work.push_back(std::move(a));
  }
  return pieces;
}

Polygon2 inset_convex_polygon(const Polygon2& polygon, double margin) {
  if (margin <= 0.0) return polygon;
  Polygon2 clipped = polygon;
  const size_t n = polygon.size();
  for (size_t e = 0; e < n && !clipped.empty(); ++e) {
    // Keep the half-plane inward_normal . (p - a) >= margin (Sutherland-Hodgman).
    const Eigen::Vector2d& a = polygon[e];
    const Eigen::Vector2d normal = inward_normal(a, polygon[(e + 1) % n]);
    Polygon2 out;
    for (size_t i = 0; i < clipped.size(); ++i) {
      const Eigen::Vector2d& p = clipped[i];
      const Eigen::Vector2d& q = clipped[(i + 1) % clipped.size()];
      const double dp = normal.dot(p - a) - margin, dq = normal.dot(q - a) - margin;
      if (dp >= 0.0) out.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + dp / (dp - dq) * (q - p));
    }
    clipped = std::move(out);
  }
  return simplify_polygon(clipped, 1e-9);
}

}  // namespace stanceplan
