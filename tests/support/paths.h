#pragma once
// Locations of the project's files and of the shared robot models, for tests.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

namespace stanceplan::test {

inline std::string source_path(const std::string& relative) {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/" + relative;
}
// The shared folder: the environment variable STANCEPLAN_SHARED_DIR when set (to check the skips
// below without rebuilding: STANCEPLAN_SHARED_DIR=/nonexistent ctest ...), else ../shared beside
// the checkout, as the build found it.
inline std::string shared_dir() {
  const char* dir = std::getenv("STANCEPLAN_SHARED_DIR");
  return dir != nullptr && *dir != '\0' ? std::string(dir) : std::string(STANCEPLAN_SHARED_DIR);
}
inline std::string shared_path(const std::string& relative) {
  return shared_dir() + "/" + relative;
}

// Why a test cannot run when shared_path(relative) is absent (a fresh clone has no ../shared), or
// nothing when it is there.
inline std::optional<std::string> missing_shared(const std::string& relative) {
  const std::string path = shared_path(relative);
  std::error_code error;
  if (std::filesystem::exists(path, error)) return std::nullopt;
  return "needs ../shared/" + relative + " (the shared robot models beside the checkout): " + path +
         " is absent";
}
// STANCEPLAN_REQUIRE_SHARED=1 (set by .ci/run): a missing shared model fails the test instead.
inline bool shared_required() {
  const char* required = std::getenv("STANCEPLAN_REQUIRE_SHARED");
  return required != nullptr && std::string(required) == "1";
}

// The temporary folder of this test process, removed with everything in it when the process ends
// (a forked child, e.g. a solver worker or a death test, has another pid and leaves it alone).
class ProcessTempRoot {
 public:
  ProcessTempRoot()
      : owner_(getpid()),
        path_(std::filesystem::temp_directory_path() / ("stanceplan_" + std::to_string(owner_))) {}
  ~ProcessTempRoot() {
    if (getpid() != owner_) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ProcessTempRoot(const ProcessTempRoot&) = delete;
  ProcessTempRoot& operator=(const ProcessTempRoot&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

// A folder of this test process's own under the system's temporary folder: CTest runs every test
// case as a separate process, in parallel, so fixed temporary paths would race.
inline std::filesystem::path temp_dir(const std::string& name) {
  static const ProcessTempRoot root;
  const auto dir = root.path() / name;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string talos_urdf() {
  return shared_path("robots/talos/robots/talos_data/robots/talos_reduced.urdf");
}
inline std::string talos_package_dir() {
  return shared_path("robots/talos");
}
inline std::string panda_urdf() {
  return shared_path("robots/panda/robots/panda_description/urdf/panda.urdf");
}
inline std::string panda_package_dir() {
  return shared_path("robots/panda");
}

}  // namespace stanceplan::test

// At the top of a test body or fixture SetUp() (a void function: it returns from it) that reads
// ../shared/<relative>: skips the test, naming what is missing, when that path is absent; fails it
// when STANCEPLAN_REQUIRE_SHARED=1. Helpers that return a value call missing_shared() instead, or
// leave the check to the tests that use them. Expands to gtest macros: include <gtest/gtest.h>.
#define STANCEPLAN_REQUIRE_SHARED(relative)                                                  \
  do {                                                                                       \
    if (const std::optional<std::string> stanceplan_missing_shared =                         \
            ::stanceplan::test::missing_shared(relative)) {                                  \
      if (::stanceplan::test::shared_required()) GTEST_FAIL() << *stanceplan_missing_shared; \
      GTEST_SKIP() << *stanceplan_missing_shared;                                            \
    }                                                                                        \
  } while (false)
