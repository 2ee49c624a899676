#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so that an
// interrupted run never leaves a truncated file.
#include <string>
#include <string_view>

namespace stanceplan {

// Throws std::runtime_error naming the path when the folder is missing or not writable.
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace stanceplan
