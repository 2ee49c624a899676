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

// "{name: value, ...}" (rad, 3 decimals) of every independent joint.
std::string joint_values(const Model& model, const Eigen::VectorXd& dofs) {
  std::string out = "{";
  for (int k = 0; k < model.num_dofs(); ++k) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3f", std::round(dofs[k] * 1000.0) / 1000.0 + 0.0);
    out += (k == 0 ? "" : ", ") + model.joints[size_t(model.dof_joints[size_t(k)])].name + ": " +
           buffer;
  }
  return out + "}";
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
      if (r.joints) out += ", joints: " + joint_values(*system.entity(r.entity).model, *r.joints);
      out += "}";
    }
    if (m.roots.empty()) out += m.contacts.empty() ? " {}" : " ";
    if (!m.contacts.empty()) {
      out += m.roots.empty() ? "contacts: [" : "\n    contacts: [";
      for (size_t k = 0; k < m.contacts.size(); ++k)
        out += (k == 0 ? "[" : ", [") + m.contacts[k].first + ", " + m.contacts[k].second + "]";
      out += "]";
    }
    out += "\n";
  }
  return out;
}

}  // namespace stanceplan
