#include "planner/io/trajectory_csv.h"

#include <cstdio>

namespace stanceplan {
namespace {

void append_number(std::string& out, double v) {
  char text[32];
  std::snprintf(text, sizeof text, ",%.17g", v);
  out += text;
}

void append_row(std::string& out, const Entity& entity, int offset, double time, int step,
                const Eigen::VectorXd& q) {
  char head[48];
  std::snprintf(head, sizeof head, "%.6f,%d", time, step);
  out += head;
  for (int k = 0; k < entity.nq(); ++k) append_number(out, q[offset + k]);
  out += "\n";
}

}  // namespace

std::string trajectory_csv(const Scene& scene, const Plan& plan, int e, double step_seconds) {
  const Entity& entity = scene.system.entity(e);
  const int offset = scene.system.offset(e);
  std::string out = "time_s,step";
  if (entity.floating()) out += ",base_x,base_y,base_z,base_qw,base_qx,base_qy,base_qz";
  const Model& model = *entity.model;
  for (int k = 0; k < model.num_dofs(); ++k) out += "," + model.joints[model.dof_joints[k]].name;
  out += "\n";
  for (size_t i = 0; i < plan.steps.size(); ++i) {
    const PlanStep& step = plan.steps[i];
    const double start = i == 0 ? 0.0 : double(i - 1) * step_seconds;  // the motion into step i
    if (step.motion) {
      const size_t n = step.motion->samples.size();
      for (size_t k = 0; k < n; ++k)
        append_row(out, entity, offset, start + step_seconds * double(k + 1) / double(n + 1),
                   int(i), step.motion->samples[k].q);
    }
    append_row(out, entity, offset, i == 0 ? 0.0 : double(i) * step_seconds, int(i), step.q);
  }
  return out;
}

}  // namespace stanceplan
