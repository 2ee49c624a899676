#pragma once
// Locations of the project's files and of the shared robot models, for tests.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace stanceplan::test {

inline std::string source_path(const std::string& relative) {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/" + relative;
}
inline std::string shared_path(const std::string& relative) {
  return std::string(STANCEPLAN_SHARED_DIR) + "/" + relative;
}
// A folder of this test process's own under the system's temporary folder: CTest runs every test
// case as a separate process, in parallel, so fixed temporary paths would race.
inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("stanceplan_" + std::to_string(getpid())) / name;
  std::filesystem::create_directories(dir);
  return dir;
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
