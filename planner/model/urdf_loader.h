#pragma once
// Builds a Model from a URDF file through urdfdom. Supports revolute, continuous, prismatic and
// fixed joints; mimic joints become dependent joints (a <mimic> on a fixed joint is ignored);
// position/effort limits; inertials; visual and collision geometry (box, cylinder, sphere, mesh).
// Floating and planar joints inside the tree are rejected. Throws InputError naming the file and
// the fault (missing file, malformed XML, two roots, unknown mimic source, unresolvable mesh URI,
// an element urdfdom could not parse, and physically meaningless values the statics would use: a
// mass < 0, a non-finite inertial origin, a zero axis, lower > upper, a negative effort or
// velocity limit, a box/sphere/cylinder size <= 0, a non-finite number), with the link or joint
// and what was expected and found. An inertia tensor no rigid body has is not an error: the
// statics never use it, so it is set to zero and listed in Model::ignored_inertias.
#include <string>

#include "planner/model/model.h"
#include "planner/model/package_path.h"

namespace stanceplan {

struct UrdfOptions {
  PackagePath packages;
  // A collision mesh that cannot be resolved is an error; a visual mesh that cannot be resolved
  // is kept with an empty mesh_path (the renderer warns and skips it) unless this is true.
  bool require_visual_meshes = false;
};

Model load_urdf(const std::string& path, const UrdfOptions& options = {});
Model load_urdf_string(const std::string& xml, const std::string& base_dir,
                       const UrdfOptions& options = {},
                       const std::string& display_name = "<string>");

}  // namespace stanceplan
