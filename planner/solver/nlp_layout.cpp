#include "planner/solver/nlp_layout.h"

namespace stanceplan {

NlpLayout::NlpLayout(const Scene& scene, const PostureRequest& request,
                     const SolverOptions& options) {
  nq = scene.system.nq();
  n = nq;
  force_block_of_task.assign(request.contacts.size(), -1);
  for (int t = 0; t < static_cast<int>(request.contacts.size()); ++t) {
    const ContactTask& task = request.contacts[t];
    if (!task.loaded) continue;
    ForceBlock block;
    block.task = t;
    block.first_column = n;
    block.num_vertices = static_cast<int>(scene.surfaces.get(task.contact.s1).vertices_S.size());
    block.bilateral = task.contact.bilateral;
    block.per_vertex = block.bilateral ? 3 : options.cone_generators;
    n += block.size();
    force_block_of_task[t] = static_cast<int>(forces.size());
    forces.push_back(block);
  }
}

}  // namespace stanceplan
