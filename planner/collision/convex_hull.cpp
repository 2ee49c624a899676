#include "planner/collision/convex_hull.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace stanceplan {
namespace {

// Principal axes of the point cloud and the extent of the points along each (ascending).
struct PrincipalExtents {
  Eigen::Matrix3d axes;    // columns, ascending extent
  Eigen::Vector3d extent;  // max - min of the projections
};

PrincipalExtents principal_extents(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : points) covariance += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  PrincipalExtents out;
  out.axes = eigen.eigenvectors();  // ascending eigenvalues = ascending spread
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& p : points) {
    const Eigen::Vector3d s = out.axes.transpose() * p;
    lo = lo.cwiseMin(s);
    hi = hi.cwiseMax(s);
  }
  out.extent = hi - lo;
  return out;
}

// Copies every point +-thickness/2 along each of the first `flat_axes` principal axes.
std::vector<Eigen::Vector3d> thicken(const std::vector<Eigen::Vector3d>& points,
                                     const Eigen::Matrix3d& axes, int flat_axes, double thickness) {
  std::vector<Eigen::Vector3d> out = points;
  for (int a = 0; a < flat_axes; ++a) {
    const Eigen::Vector3d offset = 0.5 * thickness * axes.col(a);
    const size_t n = out.size();
    for (size_t i = 0; i < n; ++i) {
      out.push_back(out[i] + offset);
      out[i] -= offset;
    }
  }
  return out;
}

// Captures what qhull writes to its error stream.
class ErrorStream {
 public:
  ErrorStream() : file_(open_memstream(&buffer_, &size_)) {}
  ~ErrorStream() {
    if (file_ != nullptr) std::fclose(file_);
    std::free(buffer_);
  }
  ErrorStream(const ErrorStream&) = delete;
  ErrorStream& operator=(const ErrorStream&) = delete;
  FILE* file() const { return file_; }
  std::string text() {
    if (file_ != nullptr) std::fflush(file_);
    return buffer_ != nullptr ? std::string(buffer_, size_) : std::string();
  }

 private:
  char* buffer_ = nullptr;
  size_t size_ = 0;
  FILE* file_ = nullptr;
};

// Vertex indices of a simplicial facet, counter-clockwise seen from outside.
Eigen::Vector3i oriented_triangle(qhT* qh, facetT* facet) {
  Eigen::Vector3i t;
  int k = 0;
  vertexT *vertex, **vertexp;
  FOREACHvertex_(facet->vertices) t[k++] = qh_pointid(qh, vertex->point);
  // qhull's convention (io_r.c, qh_printfacetNvertex_simplicial): a top-oriented facet lists
  // its vertices counter-clockwise when qh_ORIENTclock is 0, otherwise the first two are swapped.
  if (!(facet->toporient ^ qh_ORIENTclock)) std::swap(t[0], t[1]);
  return t;
}

// Runs qhull; returns the exit code and fills `hull` on success.
int run_qhull(const std::vector<Eigen::Vector3d>& points, double simplify_tolerance,
              ConvexHull* hull, std::string* error) {
  std::vector<coordT> coords(3 * points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    for (int c = 0; c < 3; ++c) coords[3 * i + c] = points[i][c];
  }
  qhT qh_storage;
  qhT* qh = &qh_storage;
  ErrorStream errors;
  qh_zero(qh, errors.file());
  std::string command = "qhull Qt";  // triangulated output
  if (simplify_tolerance > 0.0) command += " W" + std::to_string(simplify_tolerance);
  const int exitcode = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False,
                                    command.data(), nullptr, errors.file());
  if (exitcode == qh_ERRnone) {
    std::vector<int> index_of_point(points.size(), -1);
    facetT* facet;
    FORALLfacets {
      Eigen::Vector3i t = oriented_triangle(qh, facet);
      for (int c = 0; c < 3; ++c) {
        int& index = index_of_point[t[c]];
        if (index < 0) {
          index = static_cast<int>(hull->vertices.size());
          hull->vertices.push_back(points[t[c]]);
        }
        t[c] = index;
      }
      hull->triangles.push_back(t);
      hull->planes.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2],
                                facet->offset);
    }
  } else {
    *error = errors.text();
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  return exitcode;
}

// Makes every triangle's winding agree with its facet's outward normal (the geometric check wins
// over the orientation flag whenever the triangle is not degenerate).
void orient_triangles(ConvexHull* hull) {
  for (size_t f = 0; f < hull->triangles.size(); ++f) {
    Eigen::Vector3i& t = hull->triangles[f];
    const Eigen::Vector3d& a = hull->vertices[t[0]];
    const Eigen::Vector3d cross = (hull->vertices[t[1]] - a).cross(hull->vertices[t[2]] - a);
    if (cross.dot(hull->planes[f].head<3>()) < 0.0) std::swap(t[1], t[2]);
  }
}

// Closest point to p on triangle (a, b, c), by the Voronoi region of p: a vertex, an edge or the
// interior.
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double sum = va + vb + vc;
  return a + ab * (vb / sum) + ac * (vc / sum);
}

// Largest distance from a point outside the hull to the hull. The closest boundary point of an
// outside point lies on a face whose plane the point is above, so only those faces are tried.
double max_outside_distance(const ConvexHull& hull, const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const Eigen::Vector3d& p : points) {
    double distance = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < hull.triangles.size(); ++f) {
      if (hull.planes[f].head<3>().dot(p) + hull.planes[f][3] <= 0.0) continue;
      const Eigen::Vector3i& t = hull.triangles[f];
      const Eigen::Vector3d q = closest_point_on_triangle(p, hull.vertices[t[0]],
                                                          hull.vertices[t[1]], hull.vertices[t[2]]);
      distance = std::min(distance, (p - q).norm());
    }
    if (std::isfinite(distance)) largest = std::max(largest, distance);
  }
  return largest;
}

}  // namespace

ConvexHull convex_hull(const std::vector<Eigen::Vector3d>& points,
                       const ConvexHullOptions& options) {
  for (const auto& p : points) {
    if (!p.allFinite()) throw std::invalid_argument("convex hull: non-finite point");
  }
  if (points.empty()) throw std::invalid_argument("convex hull: no points");
  const PrincipalExtents principal = principal_extents(points);
  const double size = principal.extent[2];
  if (!(size > 1e-12)) {
    throw std::invalid_argument("convex hull: all points coincide");
  }
  // Directions along which the input has no thickness (relative to its size).
  int flat_axes = 0;
  while (flat_axes < 2 && principal.extent[flat_axes] <= 1e-9 * size) ++flat_axes;
  const double thickness = options.degenerate_thickness;
  if ((flat_axes > 0 || points.size() < 4) && !(thickness > 0.0)) {
    throw std::invalid_argument("convex hull: the points are " +
                                std::string(flat_axes == 2 ? "collinear" : "coplanar") +
                                " (no 3-D hull)");
  }
  if (points.size() < 4 && flat_axes == 0) flat_axes = 1;
  const std::vector<Eigen::Vector3d> input =
      flat_axes > 0 ? thicken(points, principal.axes, flat_axes, thickness) : points;

  ConvexHull hull;
  std::string error;
  int exitcode = run_qhull(input, options.simplify_tolerance, &hull, &error);
  if ((exitcode == qh_ERRsingular || exitcode == qh_ERRprec) && flat_axes == 0 && thickness > 0) {
    // Nearly flat input that qhull still finds singular: thicken along the thinnest direction.
    hull = ConvexHull();
    exitcode = run_qhull(thicken(points, principal.axes, 1, thickness), options.simplify_tolerance,
                         &hull, &error);
  }
  if (exitcode != qh_ERRnone) {
    throw std::invalid_argument("convex hull: qhull failed (exit code " + std::to_string(exitcode) +
                                "): " + error);
  }
  orient_triangles(&hull);
  hull.max_outside_distance = max_outside_distance(hull, input);
  return hull;
}

}  // namespace stanceplan
