#pragma once
// Contact surfaces extracted from a model's collision geometry (affordance extraction, as
// hpp-affordance does for HPP), for environments whose surfaces nobody measured by hand
// (`surfaces: auto` in a scenario, docs/SURFACE_FORMAT.md "Extracted surfaces"). Per link, in the
// link frame: the faces of its collision boxes, the caps of its cylinders (inscribed regular
// polygons) and the triangles of its meshes are grouped into planar regions (planar_regions.h),
// each region is classified by its outward normal in the world (support: within `slope` of up;
// lean: within `lean` of horizontal; the rest is dropped), split into convex pieces
// (convex_partition.h), shrunk by `inset`, and pieces smaller than `min_area` are dropped. Curved
// faces (cylinder sides, spheres) give nothing. Regions are per link: a face hidden by another
// link (the floor under a step) is still a surface, as a hand-written box_face would be.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "planner/contact/surface.h"
#include "planner/model/model.h"

namespace stanceplan {

enum class AffordanceClass { Support, Lean };

// "support" or "lean".
const char* to_string(AffordanceClass kind);

struct AffordanceOptions {
  double slope = 30.0;              // deg: support when the normal is within this of world up (+z)
  double lean = 15.0;               // deg: lean when the normal is within this of horizontal
  double angle_tolerance = 2.0;     // deg: coplanar merge, normals (planar_regions.h)
  double offset_tolerance = 0.005;  // m: coplanar merge, distance from the plane
  double min_area = 0.01;           // m^2: smaller pieces (after the inset) are dropped
  double inset = 0.0;               // m: every piece shrunk by this margin
  int cylinder_sides = 32;          // sides of the polygon inscribed in a cylinder's cap
};

struct Affordance {
  Surface surface;  // named support_K or lean_K
  AffordanceClass kind = AffordanceClass::Support;
  Eigen::Vector3d normal_W = Eigen::Vector3d::UnitZ();   // outward normal, world frame
  Eigen::Vector3d centroid_W = Eigen::Vector3d::Zero();  // area centroid, world frame
};

// The model's links at zero joint values, its root at T_WB. Supports first, then leans; each
// class ordered by its centroid's height in the world, then x, then y (compared to the
// micrometre), and named in that order: support_0, support_1, ..., lean_0, ... Deterministic: the
// same model and options give the same surfaces. Throws InputError when a mesh file cannot be read.
std::vector<Affordance> extract_affordances(const Model& model, const Eigen::Isometry3d& T_WB,
                                            const AffordanceOptions& options = {});

// Only the surfaces of extract_affordances, in its order.
std::vector<Surface> extract_surfaces(const Model& model, const Eigen::Isometry3d& T_WB,
                                      const AffordanceOptions& options = {});

}  // namespace stanceplan
