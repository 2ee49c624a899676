#pragma once
// What the inspector shows for one search event (a node's making, an expansion, a rejected
// candidate): the contacts with the force each carries, every joint torque against its URDF
// effort limit (E19: |tau_k| <= effort_k), and the solver's status, iterations and worst
// residuals, and the configuration entry by entry. Plain data computed from the event and the
// scene; the node section draws it.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/scene/scene.h"
#include "planner/search/search_events.h"

namespace stanceplan::gui {

struct ContactRow {
  std::string name;  // "l_sole on floor" (s1's surface name on s2's), as in captions
  bool loaded = false;
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();  // sum of the vertex forces on s1
  int vertices = 0;                                   // vertex forces summed
};

struct TorqueRow {
  std::string entity;
  std::string joint;
  double tau = 0.0;     // N m (or N for prismatic joints)
  double effort = 0.0;  // URDF limit; 0 when the URDF gives none
  double ratio() const { return effort > 0.0 ? std::abs(tau) / effort : 0.0; }
};

struct ResidualRow {
  std::string family;
  double value = 0.0;
};

struct ConfigurationRow {
  std::string entity;
  std::string name;  // "base x" ... "base qz" for floating entities, else the joint's name
  double value = 0.0;
};

struct NodeDetails {
  std::vector<ContactRow> contacts;
  std::vector<TorqueRow> torques;               // in entity and dof order
  std::vector<ResidualRow> residuals;           // largest first
  std::vector<ConfigurationRow> configuration;  // every entry of q, in the system's order
  double worst_torque_ratio = 0.0;              // max |tau| / effort over joints with a limit
  double total_force_z = 0.0;                   // N, sum of the vertical components (vs m g)
};

NodeDetails node_details(const Scene& scene, const SearchEvent& event);

}  // namespace stanceplan::gui
