#pragma once
// The wire format between the solver pool's parent and its worker processes (solver_pool.h): a
// request and a result as bytes. A minimal binary encoding: the same binary is on both ends of
// the pipe, so no byte order or versioning is needed. Throws std::runtime_error on truncated or
// malformed bytes.
#include <string>

#include "planner/solver/posture_request.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

std::string serialize(const PostureRequest& request);
PostureRequest deserialize_request(const std::string& bytes);
std::string serialize(const PostureResult& result);
PostureResult deserialize_result(const std::string& bytes);

}  // namespace stanceplan
