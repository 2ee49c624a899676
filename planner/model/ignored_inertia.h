#pragma once
// Inertia tensors the URDF loader ignores. The statics use a link's mass and centre of mass only
// (docs/METHOD.md section 4: gravity wrenches, E16); the rotational inertia plays no part. So a
// tensor that no rigid body could have (negative principal moments, the triangle inequality
// broken, non-finite entries, a non-zero tensor on a massless link), common in published robots
// exported from CAD, is reported and set to zero rather than refused.
#include <string>
#include <vector>

namespace stanceplan {

struct IgnoredInertia {
  std::string link;   // the link's name in the URDF
  std::string fault;  // what is wrong, with the numbers found
};

// One line for a model's ignored tensors, "" when there are none:
// "FILE: inertia of 2 links ignored (not used by the statics): a (FAULT), b (FAULT)".
std::string ignored_inertias_warning(const std::string& file,
                                     const std::vector<IgnoredInertia>& ignored);

}  // namespace stanceplan
