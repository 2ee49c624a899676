#include "planner/certify/certify.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "planner/collision/signed_distance.h"
#include "planner/contact/polygon.h"
#include "planner/model/kinematics.h"
#include "planner/motion/motion_options.h"
#include "planner/motion/sample_spacing.h"

namespace stanceplan {
namespace {

// docs/PLAN_FORMAT.md tolerances.
constexpr double kDistanceTol = 1e-3;              // m: on the plane, inside the polygon
constexpr double kNormalTol = 0.5 * M_PI / 180.0;  // rad: normals opposed
constexpr double kEquilibriumTol = 1e-3;           // x m|g|
constexpr double kPenetrationTol = 1e-3;           // m
// Not in docs/PLAN_FORMAT.md: numerical slack for quantities the plan states at full precision.
constexpr double kFrictionTol = 1e-6;  // N, plus 1e-6 relative
constexpr double kTorqueTol = 1e-3;    // N m: stated torques against those implied
constexpr double kLimitTol = 1e-6;     // rad or m beyond a joint limit

class Checker {
 public:
  Checker(const Scene& scene, double friction, const Plan& plan)
      : plan_(plan), friction_(friction), scene_(scene), system_(scene.system) {}

  CertifyReport run() {
    const auto& steps = plan_.steps;
    for (size_t i = 0; i < steps.size(); ++i)
      check_step(int(i), steps[i], i > 0 ? &steps[i - 1] : nullptr);
    if (steps.empty()) note("sequence", "", 1.0, 0.0, -1, "the plan has no step");
    CertifyReport report;  // the checks that applied, in a fixed order
    for (const char* name : kOrder)
      if (checks_.count(name)) report.checks.push_back(checks_.at(name));
    report.first_failed_step = first_failed_step_;
    return report;
  }

 private:
  static constexpr const char* kOrder[] = {
      "solver status",      "sequence",         "contact plane",     "contact polygon",
      "contact normals",    "force points",     "equilibrium force", "equilibrium moment",
      "unilateral",         "friction",         "joint limits",      "torque limits",
      "torque consistency", "quaternion norm",  "interpenetration",  "motion status",
      "motion joint step",  "motion point step"};

  // Keeps the worst violation of each check, with its step and what it was.
  void note(const std::string& name, const std::string& unit, double violation, double tolerance,
            int step, const std::string& detail) {
    auto [it, inserted] =
        checks_.try_emplace(name, CheckResult{name, unit, 0.0, tolerance, step, ""});
    CheckResult& c = it->second;
    if (step >= 0 && !(violation <= tolerance) &&
        (first_failed_step_ < 0 || step < first_failed_step_))
      first_failed_step_ = step;
    if (violation > c.worst || (std::isnan(violation) && !std::isnan(c.worst))) {
      c.worst = std::isnan(violation) ? INFINITY : violation;
      c.step = step;
      c.detail = where_ + detail;
    }
  }

  std::string id(SurfaceRef r) const { return scene_.surfaces.id(system_, r); }

  // A step is a posture only when its solve succeeded: the last iterate of a failed solve (kept
  // by `posture --out` so that it can be looked at) is never accepted, whatever its residuals.
  void check_status(int i, const PlanStep& step) {
    const bool failed = step.status != PostureStatus::Solved || !plan_.failed.empty();
    const std::string why =
        "the last iterate of a failed solve (" +
        (plan_.failed.empty() ? std::string(to_string(step.status)) : plan_.failed) + ")";
    note("solver status", "", failed ? 1.0 : 0.0, 0.0, i, failed ? why : "");
  }

  // --- adjacency and step semantics (docs/METHOD.md section 2)
  void check_sequence(int i, const PlanStep& step, const PlanStep* previous) {
    auto bad = [&](const std::string& why) { note("sequence", "", 1.0, 0.0, i, why); };
    note("sequence", "", 0.0, 0.0, i, "");
    std::vector<Contact> loaded, touched;
    for (const PlanContact& c : step.contacts) {
      touched.push_back(c.contact);
      if (c.loaded) loaded.push_back(c.contact);
    }
    const Stance touched_stance(touched), loaded_stance(loaded);
    if (!previous) {
      if (step.action != "initial") bad("step 0 is not \"initial\"");
      if (loaded.size() != touched.size()) bad("step 0 does not load every contact");
      if (!(touched_stance == step.stance)) bad("step 0's contacts are not its stance");
      return;
    }
    const Stance& before = previous->stance;
    const Stance& after = step.stance;
    if (!step.changed) return bad("no changed_contact");
    const Contact& c = *step.changed;
    if (step.action == "add") {
      if (before.find(c) >= 0 || after.find(c) < 0 || after.size() != before.size() + 1 ||
          !(after.without(after.find(c)) == before))
        bad("stance " + std::to_string(i) + " is not stance " + std::to_string(i - 1) + " plus " +
            id(c.s1) + "-" + id(c.s2));
      if (!(touched_stance == after) || !(loaded_stance == before))
        bad("an add step must touch sigma_i and load sigma_{i-1}");
    } else if (step.action == "remove") {
      const int k = before.find(c);
      if (k < 0 || after.find(c) >= 0 || !(before.without(k) == after))
        bad("stance " + std::to_string(i) + " is not stance " + std::to_string(i - 1) + " minus " +
            id(c.s1) + "-" + id(c.s2));
      else if (before.contacts()[k].fixed)
        bad("the fixed contact " + id(c.s1) + "-" + id(c.s2) + " is removed");
      if (!(touched_stance == before) || !(loaded_stance == after))
        bad("a remove step must touch sigma_{i-1} and load sigma_i");
    } else {
      bad("action \"" + step.action + "\" after step 0");
    }
  }

  // --- contact geometry of every touched contact
  void check_contacts(int i, const PlanStep& step) {
    for (const PlanContact& pc : step.contacts) {
      const Contact& c = pc.contact;
      const Surface& s1 = scene_.surfaces.get(c.s1);
      const Surface& s2 = scene_.surfaces.get(c.s2);
      const Eigen::Isometry3d T1 = data_[c.s1.entity].T_WL[s1.link] * s1.T_LS;
      const Eigen::Isometry3d T2 = data_[c.s2.entity].T_WL[s2.link] * s2.T_LS;
      const std::string name = id(c.s1) + " on " + id(c.s2);
      if (s1.is_point()) {
        check_point_contact(i, T1.translation(), s1.radius, T2, s2.vertices_S, name);
        continue;
      }
      const double angle =
          std::acos(std::clamp(-T1.linear().col(2).dot(T2.linear().col(2)), -1.0, 1.0));
      note("contact normals", "rad", angle, kNormalTol, i, name);
      const auto& poly = s2.vertices_S;
      for (int v = 0; v < int(s1.vertices_S.size()); ++v) {
        const Eigen::Vector3d p_S2 =
            T2.inverse() * (T1 * Eigen::Vector3d(s1.vertices_S[v].x(), s1.vertices_S[v].y(), 0.0));
        note("contact plane", "m", std::abs(p_S2.z()), kDistanceTol, i,
             name + ", vertex " + std::to_string(v));
        const double outside = std::max(0.0, distance_outside(poly, p_S2.head<2>()));
        note("contact polygon", "m", outside, kDistanceTol, i,
             name + ", vertex " + std::to_string(v));
      }
    }
  }

  // A point contact (a sphere of radius r centred at c_W): the centre r above s2's plane (E9) and,
  // in s2's plane, inside its polygon (E10-E11); no orientation to check.
  void check_point_contact(int i, const Eigen::Vector3d& c_W, double radius,
                           const Eigen::Isometry3d& T2, const std::vector<Eigen::Vector2d>& poly,
                           const std::string& name) {
    const Eigen::Vector3d c_S2 = T2.inverse() * c_W;
    note("contact plane", "m", std::abs(c_S2.z() - radius), kDistanceTol, i,
         name + ", the centre not one radius from the plane");
    note("contact polygon", "m", std::max(0.0, distance_outside(poly, c_S2.head<2>())),
         kDistanceTol, i, name + ", the point");
  }

  // Where a contact's forces may act, in the world: s1's vertices, or for a point contact the
  // point one radius below the centre along s2's normal.
  std::vector<Eigen::Vector3d> force_points(const Contact& c) const {
    const Surface& s1 = scene_.surfaces.get(c.s1);
    const Eigen::Isometry3d& T1 = data_[c.s1.entity].T_WL[s1.link];
    std::vector<Eigen::Vector3d> points;
    for (const Eigen::Vector3d& v : s1.vertices_L()) points.push_back(T1 * v);
    if (s1.is_point()) {
      const Surface& s2 = scene_.surfaces.get(c.s2);
      points[0] -= s1.radius * (data_[c.s2.entity].T_WL[s2.link].linear() * s2.normal_L());
    }
    return points;
  }

  // --- forces: where they act, unilaterality, friction
  void check_forces(int i, const PlanStep& step) {
    for (const VertexForce& f : step.forces) {
      const PlanContact& pc = step.contacts[f.contact];
      const std::string name = id(pc.contact.s1) + " on " + id(pc.contact.s2);
      if (!pc.loaded)
        note("force points", "m", 1.0, kDistanceTol, i, name + " carries force but is not loaded");
      double nearest = INFINITY;
      for (const Eigen::Vector3d& p : force_points(pc.contact))
        nearest = std::min(nearest, (p - f.point_W).norm());
      note("force points", "m", nearest, kDistanceTol, i,
           name + (scene_.surfaces.get(pc.contact.s1).is_point()
                       ? ": the force's point is not one radius below the centre"
                       : ": no vertex of s1 at the force's point"));
      if (pc.contact.bilateral) continue;
      const Surface& s2 = scene_.surfaces.get(pc.contact.s2);
      const Eigen::Vector3d n = data_[pc.contact.s2.entity].T_WL[s2.link].linear() * s2.normal_L();
      const double fn = f.force_W.dot(n);
      const double ft = (f.force_W - fn * n).norm();
      note("unilateral", "N", std::max(0.0, -fn), kFrictionTol, i, name);
      note("friction", "N", std::max(0.0, ft - friction_ * fn - 1e-6 * f.force_W.norm()),
           kFrictionTol, i, name);
    }
  }

  // --- E16-E17 for every floating robot and object. Every force is taken at its stated point,
  // which "force points" checked: for a point contact the point on s2's plane, c - r z2, so its
  // moment includes the couple -r z2 x f of the force taken at the centre (E17, E18 below).
  void check_equilibrium(int i, const PlanStep& step) {
    for (int e = 0; e < system_.num_entities(); ++e) {
      const Entity& entity = system_.entity(e);
      if (!entity.floating() || entity.model->total_mass <= 0.0) continue;
      const Eigen::Vector3d weight = entity.model->total_mass * scene_.gravity;
      Eigen::Vector3d force = weight, moment = center_of_mass(entity, data_[e]).cross(weight);
      for (const VertexForce& f : step.forces) {
        const Contact& c = step.contacts[f.contact].contact;
        const double sign = (c.s1.entity == e ? 1.0 : 0.0) - (c.s2.entity == e ? 1.0 : 0.0);
        force += sign * f.force_W;
        moment += sign * f.point_W.cross(f.force_W);
      }
      const double scale = entity.model->total_mass * scene_.gravity.norm();
      note("equilibrium force", "m|g|", force.norm() / scale, kEquilibriumTol, i, entity.name);
      note("equilibrium moment", "m|g| m", moment.norm() / scale, kEquilibriumTol, i, entity.name);
    }
  }

  // --- joint limits, torque limits and tau + sum J^T f + J_com^T m g = 0
  void check_joints(int i, const PlanStep& step) {
    for (int e = 0; e < system_.num_entities(); ++e) {
      const Entity& entity = system_.entity(e);
      const Model& model = *entity.model;
      if (entity.floating())
        note("quaternion norm", "", std::abs(step.q.segment<4>(system_.offset(e) + 3).norm() - 1.0),
             1e-6, i, entity.name);
      if (model.num_dofs() == 0) continue;
      const int first = system_.offset(e) + entity.first_dof();
      for (int k = 0; k < model.num_dofs(); ++k) {
        const Joint& joint = model.joints[model.dof_joints[k]];
        if (!joint.has_position_limits) continue;
        const double v = step.q[first + k];
        note("joint limits", "rad|m", std::max({0.0, joint.lower - v, v - joint.upper}), kLimitTol,
             i, entity.name + "/" + joint.name);
      }
      if (entity.kind == EntityKind::Object) continue;
      if (e >= int(step.torques.size()) || step.torques[e].size() != model.num_dofs()) {
        note("torque consistency", "N m", INFINITY, kTorqueTol, i,
             entity.name + ": no torques in the plan");
        continue;
      }
      const Eigen::VectorXd implied = implied_torques(e, step);
      for (int k = 0; k < model.num_dofs(); ++k) {
        const Joint& joint = model.joints[model.dof_joints[k]];
        const double tau = step.torques[e][k];
        if (joint.effort > 0.0)
          note("torque limits", "x effort", std::max(0.0, std::abs(tau) / joint.effort - 1.0), 1e-6,
               i, entity.name + "/" + joint.name);
        note("torque consistency", "N m", std::abs(tau - implied[k]), kTorqueTol, i,
             entity.name + "/" + joint.name);
      }
    }
  }

  // tau = -(sum over received forces J_p^T f + J_com^T m g), restricted to the joint columns.
  Eigen::VectorXd implied_torques(int e, const PlanStep& step) const {
    const Entity& entity = system_.entity(e);
    Eigen::MatrixXd J(3, entity.nq());
    Eigen::VectorXd generalized = Eigen::VectorXd::Zero(entity.nq());
    for (const VertexForce& f : step.forces) {
      const Contact& c = step.contacts[f.contact].contact;
      for (const auto& [ref, sign] : {std::pair{c.s1, 1.0}, std::pair{c.s2, -1.0}}) {
        if (ref.entity != e) continue;
        point_jacobian_world(entity, data_[e], scene_.surfaces.get(ref).link, f.point_W, J);
        generalized += sign * J.transpose() * f.force_W;
      }
    }
    center_of_mass_jacobian(entity, data_[e], J);
    generalized += J.transpose() * (entity.model->total_mass * scene_.gravity);
    return -generalized.tail(entity.model->num_dofs());
  }

  // --- no interpenetration beyond 1 mm, except pairs touching through a contact of this step
  void check_collisions(int i, const PlanStep& step) {
    if (!scene_.collision) return;
    const CollisionModel& model = *scene_.collision;
    CollisionData work(system_, model);
    work.update(model, data_);
    for (int p = 0; p < int(model.pairs().size()); ++p) {
      const CollisionLink& a = model.links()[model.pairs()[p].a];
      const CollisionLink& b = model.links()[model.pairs()[p].b];
      bool touching = false;
      for (const PlanContact& pc : step.contacts) {
        const int la = scene_.surfaces.get(pc.contact.s1).link,
                  lb = scene_.surfaces.get(pc.contact.s2).link;
        const int ea = pc.contact.s1.entity, eb = pc.contact.s2.entity;
        if ((a.entity == ea && a.link == la && b.entity == eb && b.link == lb) ||
            (a.entity == eb && a.link == lb && b.entity == ea && b.link == la))
          touching = true;
      }
      if (touching) continue;
      const double d = signed_distance(model, work, p).distance;
      const auto name = [&](const CollisionLink& l) {
        return system_.entity(l.entity).name + "/" +
               system_.entity(l.entity).model->links[l.link].name;
      };
      note("interpenetration", "m", std::max(0.0, -d), kPenetrationTol, i,
           name(a) + " and " + name(b));
    }
  }

  // The checks of one configuration with its contacts, forces and torques (a step or a sample).
  void check_posture(int i, const PlanStep& step) {
    data_ = system_kinematics(system_, step.q);
    check_contacts(i, step);
    check_forces(i, step);
    check_equilibrium(i, step);
    check_joints(i, step);
    check_collisions(i, step);
  }

  void check_step(int i, const PlanStep& step, const PlanStep* previous) {
    check_status(i, step);
    check_sequence(i, step, previous);
    check_posture(i, step);
    if (step.motion && previous) check_motion(i, step, *previous);
  }

  // --- the motion into step i: every sample as a step holding step i-1's stance, every contact
  // loaded; then its status and the spacing of consecutive configurations (docs/PLAN_FORMAT.md).
  void check_motion(int i, const PlanStep& step, const PlanStep& previous) {
    const StepMotion& motion = *step.motion;
    const bool solved = motion.status == MotionStatus::Solved;
    note("motion status", "", solved ? 0.0 : 1.0, 0.0, i,
         solved ? "" : std::string(to_string(motion.status)) + ": " + motion.message);
    PlanStep held;
    for (const Contact& c : previous.stance.contacts()) held.contacts.push_back({c, true});
    for (size_t k = 0; k < motion.samples.size(); ++k) {
      where_ = "motion sample " + std::to_string(k) + ": ";
      held.q = motion.samples[k].q;
      held.forces = motion.samples[k].forces;
      held.torques = motion.samples[k].torques;
      check_posture(i, held);
    }
    where_.clear();
    check_spacing(i, step, previous);
  }

  void check_spacing(int i, const PlanStep& step, const PlanStep& previous) {
    std::vector<SurfaceRef> surfaces;
    for (const PlanStep* s : {&previous, &step})
      for (const PlanContact& pc : s->contacts) {
        surfaces.push_back(pc.contact.s1);
        surfaces.push_back(pc.contact.s2);
      }
    SampleSpacing spacing(scene_, surfaces);
    const MotionOptions limits;  // the defaults: a motion with looser options is not certified
    const std::vector<MotionSample>& samples = step.motion->samples;
    const Eigen::VectorXd* a = &previous.q;
    for (size_t k = 0; k <= samples.size(); ++k) {
      const Eigen::VectorXd& b = k < samples.size() ? samples[k].q : step.q;
      const SpacingMeasure m = spacing.measure(*a, b);
      const std::string between =
          (k == 0 ? "step " + std::to_string(i - 1) : "motion sample " + std::to_string(k - 1)) +
          " to " +
          (k < samples.size() ? "motion sample " + std::to_string(k)
                              : "step " + std::to_string(i)) +
          ": ";
      note("motion joint step", "rad", m.joint, limits.joint_spacing * (1.0 + 1e-9), i,
           between + spacing.joint_name(m));
      note("motion point step", "m", m.point, limits.point_spacing * (1.0 + 1e-9), i,
           between + spacing.surface_name(m));
      a = &b;
    }
  }

  const Plan& plan_;
  const double friction_;
  const Scene& scene_;
  const System& system_;
  std::vector<ModelData> data_;
  std::map<std::string, CheckResult> checks_;
  std::string where_;  // "motion sample 3: " while a sample is checked
  int first_failed_step_ = -1;
};

}  // namespace

bool CertifyReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed(); });
}

CertifyReport certify(const Scene& scene, double friction, const Plan& plan) {
  return Checker(scene, friction, plan).run();
}

CertifyReport certify(const LoadedPlan& plan) {
  return certify(plan.scene, plan.friction, plan.plan);
}

const CheckResult* CertifyReport::first_failure() const {
  for (const CheckResult& c : checks)
    if (!c.passed()) return &c;
  return nullptr;
}

}  // namespace stanceplan
