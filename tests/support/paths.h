#pragma once
// Locations of the project's files and of the shared robot models, for tests.
#include <string>

namespace stanceplan::test {

inline std::string source_path(const std::string& relative) {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/" + relative;
}
inline std::string shared_path(const std::string& relative) {
  return std::string(STANCEPLAN_SHARED_DIR) + "/" + relative;
}
inline std::string talos_urdf() {
  return shared_path("robots/talos/robots/talos_data/robots/talos_reduced.urdf");
}
inline std::string talos_package_dir() { return shared_path("robots/talos"); }
inline std::string panda_urdf() {
  return shared_path("robots/panda/robots/panda_description/urdf/panda.urdf");
}
inline std::string panda_package_dir() { return shared_path("robots/panda"); }

}  // namespace stanceplan::test
