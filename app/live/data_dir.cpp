#include "app/live/data_dir.h"

#include <system_error>

#include "planner/util/input_error.h"

namespace stanceplan::app {
namespace {

namespace fs = std::filesystem;

bool holds_scenarios(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "scenarios", ec);
}

fs::path installed_dir(const fs::path& executable) {
  return executable.parent_path().parent_path() / "share" / "stanceplan";
}

}  // namespace

std::optional<fs::path> find_data_dir(const fs::path& executable) {
  if (!executable.empty() && holds_scenarios(installed_dir(executable)))
    return installed_dir(executable);
#ifdef STANCEPLAN_DATA_SOURCE_DIR
  if (holds_scenarios(STANCEPLAN_DATA_SOURCE_DIR)) return fs::path(STANCEPLAN_DATA_SOURCE_DIR);
#endif
  return std::nullopt;
}

fs::path current_executable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

std::string default_scenario_path() {
  const fs::path exe = current_executable();
  if (const auto dir = find_data_dir(exe)) {
    const fs::path path = *dir / kDefaultScenario;
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) return path.string();
    throw InputError(path.string() + ": the default scenario is missing from the data folder " +
                     dir->string());
  }
  std::string searched = installed_dir(exe).string();
#ifdef STANCEPLAN_DATA_SOURCE_DIR
  searched += " and " + std::string(STANCEPLAN_DATA_SOURCE_DIR);
#endif
  throw InputError("no data folder with scenarios/ found (searched " + searched +
                   "); give a scenario file: stanceplan SCENARIO.yaml");
}

}  // namespace stanceplan::app
