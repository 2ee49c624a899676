#pragma once
// The outcome of one solve, as a value: the search treats infeasible, iteration-limit and
// numerical failures as candidate rejections (never exceptions).
#include <Eigen/Core>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "planner/contact/contact.h"

namespace stanceplan {

enum class PostureStatus { Solved, Infeasible, IterationLimit, NumericalFailure };
const char* to_string(PostureStatus status);

// The violation of a constraint family that is as significant as 1 (what worst_family() divides
// by): 1 mm or 1 mrad for geometry (contact_geometry, polygon, collision, joint_limits), 0.1 % of
// the weight for equilibrium (its rows are divided by m|g|), 0.1 % of the effort limit for
// torque_limits, 0.1 N for a force coefficient below 0 (friction), and 1 for the quaternion norm:
// the kinematics normalise phi, so a norm off 1 moves nothing until phi nears 0.
double residual_unit(const std::string& family);

// The force at one vertex of s1 of a loaded contact, applied BY s2's link ON s1's link.
struct VertexForce {
  int contact = -1;  // index into PostureRequest::contacts
  int vertex = -1;   // index into s1's polygon
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();
};

struct PostureResult {
  PostureStatus status = PostureStatus::NumericalFailure;
  std::string message;  // Ipopt's status and, when not solved, the worst family
  Eigen::VectorXd q;    // the final iterate (meaningful when solved)
  std::vector<VertexForce> forces;
  std::vector<Eigen::VectorXd>
      torques;                        // per entity: actuation torque of every dof (empty if none)
  std::vector<Placement> placements;  // per request contact: realised placement of s1 in s2
  int iterations = 0;
  double time_ms = 0.0;
  double objective = 0.0;
  // Worst violation of each constraint family at the final iterate (0 when satisfied), e.g.
  // "contact_geometry", "polygon", "equilibrium", "torque_limits", "collision", "quaternion",
  // "joint_limits", "friction".
  std::map<std::string, double> residuals;
  // For the families of one contact (contact_geometry, polygon): the request contact whose row is
  // the family's worst.
  std::map<std::string, int> residual_contacts;
  // The family whose residual is largest in its own unit (residual_unit), among those whose
  // residual exceeds `beyond`: the one to blame ("" when none does).
  std::string worst_family(double beyond = -1.0) const;
  // "" when every number of the solution (q, forces, torques, placements) is finite; else the
  // first that is not, e.g. "q[12]" or "force 3".
  std::string non_finite_part() const;
  // With SolverOptions::diagnose_infeasibility: the family without which the request is solved
  // ("torque_limits", "collision"), or "" when the geometry/statics themselves are infeasible.
  std::string blocking_family;

  // A solve that did not run, or stopped, for a reason outside the program: "cancelled", a
  // solver process that died, an unusable initial guess.
  static PostureResult numerical_failure(std::string why) {
    PostureResult r;
    r.message = std::move(why);  // status: NumericalFailure (the default)
    return r;
  }
};

}  // namespace stanceplan
