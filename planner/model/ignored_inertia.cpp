#include "planner/model/ignored_inertia.h"

namespace stanceplan {

std::string ignored_inertias_warning(const std::string& file,
                                     const std::vector<IgnoredInertia>& ignored) {
  if (ignored.empty()) return "";
  std::string line = file + ": inertia of " + std::to_string(ignored.size()) +
                     (ignored.size() == 1 ? " link" : " links") +
                     " ignored (not used by the statics): ";
  for (size_t i = 0; i < ignored.size(); ++i) {
    if (i > 0) line += ", ";
    line += ignored[i].link + " (" + ignored[i].fault + ")";
  }
  return line;
}

}  // namespace stanceplan
