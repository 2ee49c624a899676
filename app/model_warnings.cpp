#include "app/model_warnings.h"

#include <ostream>
#include <set>
#include <string>

namespace stanceplan::app {

void print_model_warnings(const Scene& scene, std::ostream& err) {
  std::set<std::string> printed;
  for (const Entity& entity : scene.system.entities()) {
    const Model& model = *entity.model;
    const std::string line = ignored_inertias_warning(
        model.source_file.empty() ? model.name : model.source_file, model.ignored_inertias);
    if (!line.empty() && printed.insert(line).second)
      err << "stanceplan: warning: " << line << "\n";
  }
}

}  // namespace stanceplan::app
