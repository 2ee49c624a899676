#pragma once
// Convex pieces of a planar region (affordances.h): a contact surface must be one convex polygon
// (surface.h), but a region read from geometry may be non-convex (an L-shaped floor) or have holes
// (a floor around a column's footprint). The partition cuts at reflex vertices: each cut extends
// an edge at a reflex vertex into the polygon until it meets the boundary, which leaves that vertex
// convex on both sides and makes no new reflex vertex, so a polygon with r reflex vertices gives at
// most r + 1 pieces (an L-shape gives 2). Of the two edges at a reflex vertex, the one whose
// extension is shorter is extended. Holes are first joined to the outer boundary by a bridge from
// their rightmost vertex along +x to the nearest boundary point (the first hole joined is the
// rightmost one, so a bridge never crosses a hole not yet joined). Hertel-Mehlhorn on a
// triangulation would also give convex pieces, but up to four times the fewest; cutting needs no
// triangulation and is optimal for the rectilinear shapes of buildings and furniture.
#include <Eigen/Core>
#include <vector>

namespace stanceplan {

using Polygon2 = std::vector<Eigen::Vector2d>;

// Twice the signed area: > 0 for a counter-clockwise polygon.
double signed_area2(const Polygon2& polygon);

// Drops repeated vertices and vertices within `tolerance` (m) of the line through their
// neighbours, until none is left; fewer than 3 vertices left means no polygon.
Polygon2 simplify_polygon(const Polygon2& polygon, double tolerance);

// Convex pieces of the region bounded by `outer` (counter-clockwise) minus `holes` (each
// clockwise, inside `outer`, disjoint), every piece counter-clockwise and strictly convex after
// simplify_polygon(tolerance). Vertices within `tolerance` of a straight angle count as straight.
std::vector<Polygon2> convex_partition(const Polygon2& outer, const std::vector<Polygon2>& holes,
                                       double tolerance);

// The convex counter-clockwise polygon shrunk by `margin` (m): every edge moved inward by it. Empty
// when nothing is left.
Polygon2 inset_convex_polygon(const Polygon2& polygon, double margin);

}  // namespace stanceplan
