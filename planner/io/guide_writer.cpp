#include "planner/io/guide_writer.h"

#include <cmath>
#include <cstdio>

namespace stanceplan {
namespace {

// "[x, y, z]" with `decimals` digits, never "-0.000".
std::string numbers(const Eigen::Vector3d& v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::round(v[i] * scale) / scale + 0.0);
    out += (i > 0 ? ", " : "") + std::string(buffer);
  }
  return out + "]";
}

}  // namespace

std::string guide_section(const System& system, const std::vector<GuideMilestone>& milestones,
                          const std::vector<std::string>& comment) {
  std::string out;
  for (const std::string& line : comment) out += "# " + line + "\n";
  out += "guide:\n";
  for (const GuideMilestone& m : milestones) {
    out += "  -";
    for (size_t k = 0; k < m.roots.size(); ++k) {
      const GuideMilestone::Root& r = m.roots[k];
      out += (k == 0 ? " " : "\n    ") + system.entity(r.entity).name +
             ": {base_position: " + numbers(r.position, 3);
      if (r.rpy) out += ", base_rpy: " + numbers(*r.rpy, 4);
      out += "}";
    }
    if (m.roots.empty()) out += " {}";
    out += "\n";
  }
  return out;
}

}  // namespace stanceplan
