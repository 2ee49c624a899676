#pragma once
// The outcome of one solve, as a value: the search treats infeasible, iteration-limit and
// numerical failures as candidate rejections (never exceptions).
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "planner/contact/contact.h"

namespace stanceplan {

enum class PostureStatus { Solved, Infeasible, IterationLimit, NumericalFailure };
const char* to_string(PostureStatus status);

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
  std::string worst_family() const;  // the family with the largest residual
  // "" when every number of the solution (q, forces, torques, placements) is finite; else the
  // first that is not, e.g. "q[12]" or "force 3".
  std::string non_finite_part() const;
  // With SolverOptions::diagnose_infeasibility: the family without which the request is solved
  // ("torque_limits", "collision"), or "" when the geometry/statics themselves are infeasible.
  std::string blocking_family;
};

}  // namespace stanceplan
