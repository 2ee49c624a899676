#pragma once
// Where the program finds its own scenarios/ and assets/: beside the executable when installed
// (PREFIX/bin/stanceplan reads PREFIX/share/stanceplan, put there by the install() rules of
// app/CMakeLists.txt), else in the source tree the build was configured from (compiled in as
// STANCEPLAN_DATA_SOURCE_DIR). Never the current directory: the main job works from anywhere.
#include <filesystem>
#include <optional>
#include <string>

namespace stanceplan::app {

// The main job's scenario when none is given. One constant: the paper's first scenario.
inline constexpr const char* kDefaultScenario = "scenarios/humanoid_sit_desk.yaml";

// The installed data folder of `executable` (PREFIX/share/stanceplan when it holds scenarios/),
// else the build's source tree when it still holds scenarios/; nullopt when neither does.
std::optional<std::filesystem::path> find_data_dir(const std::filesystem::path& executable);
// This process's executable (/proc/self/exe).
std::filesystem::path current_executable();
// The default scenario's path; throws InputError naming the places searched when it is missing.
std::string default_scenario_path();

}  // namespace stanceplan::app
