#include "app/collision_matrix_note.h"

#include <ostream>

namespace stanceplan::app {

void print_computed_collision_matrices(const Scene& scene, std::ostream& err) {
  if (!scene.collision) return;
  for (const CollisionModel::ComputedMatrix& computed : scene.collision->computed_matrices()) {
    const CollisionMatrix& matrix = computed.matrix;
    if (matrix.num_sampled() == 0) continue;  // nothing beyond what the model never checks anyway
    err << "stanceplan: " << scene.system.entity(computed.entity).name << ": "
        << matrix.pairs.size() << " self-collision "
        << (matrix.pairs.size() == 1 ? "pair" : "pairs")
        << " disabled (computed: " << describe_counts(matrix)
        << "); write them with stanceplan inspect --collision-matrix --srdf-out FILE\n";
  }
}

}  // namespace stanceplan::app
