#pragma once
// One candidate's solver request in a file (stanceplan plan --requests DIR), to be solved again
// alone (stanceplan replay): a search's rejected candidate examined with Ipopt's own output, or
// under other solver settings, without the search around it. The file is a first line naming the
// format, then the solver pool's wire bytes (planner/solver/solver_wire.h), which carry no version
// of their own: a file is read by the build that wrote it.
#include <string>

#include "planner/solver/posture_request.h"

namespace stanceplan {

inline constexpr const char* kRequestFileHeader = "stanceplan/request@1\n";

// Atomic (planner/util/atomic_file.h); std::runtime_error naming the path when it cannot be
// written.
void write_request_file(const std::string& path, const PostureRequest& request);

// InputError naming the file: missing, not a request file (its first bytes), or cut short.
PostureRequest read_request_file(const std::string& path);

}  // namespace stanceplan
