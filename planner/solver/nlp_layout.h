#pragma once
// Where each variable of the IK-statics program lives: x = [ q (System::nq) | lambda blocks ].
// One lambda block per loaded contact: for each vertex of s1, K cone coefficients (E5, lambda >= 0
// by E7) or, for a bilateral contact, the 3 world components of the force (free).
#include <vector>

#include "planner/scene/scene.h"
#include "planner/solver/posture_request.h"

namespace stanceplan {

struct ForceBlock {
  int task = -1;  // index into PostureRequest::contacts
  int first_column = 0;
  int num_vertices = 0;
  int per_vertex = 0;  // K (unilateral) or 3 (bilateral)
  bool bilateral = false;
  int size() const { return num_vertices * per_vertex; }
};

struct NlpLayout {
  NlpLayout(const Scene& scene, const PostureRequest& request, const SolverOptions& options);

  int nq = 0;
  int n = 0;
  std::vector<ForceBlock> forces;
  std::vector<int> force_block_of_task;  // -1 for unloaded contacts
};

}  // namespace stanceplan
