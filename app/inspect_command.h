#pragma once
// `stanceplan inspect MODEL.urdf`: what a model is (kind, dofs, joints and limits, mass, links,
// surfaces, collision geometry), as text or one JSON object.
#include <iosfwd>
#include <string>
#include <vector>

namespace stanceplan::app {

struct InspectOptions {
  std::string urdf;
  std::string surfaces;  // optional surface file
  std::string srdf;      // optional SRDF (disabled collision pairs)
  std::vector<std::string> package_paths;
  std::string kind = "auto";  // auto | fixed | floating | object | environment
  bool json = false;
};

// Throws InputError on bad input.
int run_inspect(const InspectOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
