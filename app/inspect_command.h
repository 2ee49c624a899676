#pragma once
// `stanceplan inspect MODEL.urdf`: what a model is (kind, dofs, joints and limits, mass, links,
// surfaces, collision geometry), as text or one JSON object; with --collision-matrix, the link
// pairs a computed self-collision matrix disables, optionally written as an SRDF; with --png, a
// picture of its contact surfaces.
#include <cstdint>
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
  // --collision-matrix: print the computed self-collision matrix instead of the description
  // (planner/collision/collision_matrix.h); --srdf-out writes it as an SRDF.
  bool collision_matrix = false;
  std::string srdf_out;
  int samples = 1000;
  uint64_t seed = 0;
  bool never = false;
  // --png: the model with its surfaces drawn and named (app/inspect_figure.h), from --view.
  std::string png;
  std::string view = "three-quarter";
};

// Throws InputError on bad input.
int run_inspect(const InspectOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
