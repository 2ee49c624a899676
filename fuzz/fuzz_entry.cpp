// The libFuzzer entry point of one target; fuzz/CMakeLists.txt compiles it once per target with
// STANCEPLAN_FUZZ_TARGET set to Scenario, Surfaces, Plan, Urdf, Srdf or Request (see
// fuzz/fuzz_inputs.h).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "fuzz/fuzz_inputs.h"

namespace {

using stanceplan::fuzz::Target;

// This process's own work folder (several fuzzers may run at once).
const std::filesystem::path& work_dir() {
  static const std::filesystem::path work = [] {
    const auto dir =
        std::filesystem::temp_directory_path() / ("stanceplan_fuzz_" + std::to_string(getpid()));
    stanceplan::fuzz::prepare_work_dir(dir);
    return dir;
  }();
  return work;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // An InputError is the expected outcome of bad input; anything else escapes and is reported.
  stanceplan::fuzz::run_one(Target::STANCEPLAN_FUZZ_TARGET,
                            {reinterpret_cast<const char*>(data), size}, work_dir());
  return 0;
}
