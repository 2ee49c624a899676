#pragma once
// The quasi-static motion between two consecutive plan steps (docs/METHOD.md section 7, "Motion
// between stances"). With sigma the stance reached by the first step (touched by both steps'
// configurations: an add step touches its new stance, a remove step the stance before it), the
// path from q_a to q_b keeps every contact of sigma at its placement and loaded, and is made of
//   lift:     when the first step removed a contact, its s1 leaves s2 along s2's normal up to the
//             clearance (E9 with a standoff, the placement held: planner/solver ContactTask);
//   travel:   the configurations interpolated between the ends of lift and approach (joints
//             linearly, roots by slerp: configuration_path.h) as the E22 reference q_ref;
//   approach: when the second step adds a contact, the lift of its s1 from q_b, run backwards.
// Each sample is projected into F_sigma by the IK-statics program (E6-E20, warm started from the
// previous sample: one PostureSolver, one request reused); where a projection fails or lands
// farther than the spacing from its predecessor, the interpolation step is halved (bisection).
// When the travel still fails (its straight reference through an obstacle, or the projection stuck
// behind one), a detour on the stance manifold replaces it (stance_rrt.h: a bidirectional RRT
// whose nodes are projected samples, seeded with the straight samples found).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/motion/motion_options.h"
#include "planner/motion/sample_spacing.h"
#include "planner/plan/plan.h"
#include "planner/solver/posture_solver.h"

namespace stanceplan {

struct StepMotionResult {
  StepMotion motion;   // status, message, samples strictly between the two steps
  int solves = 0;      // IK-statics solves, failed ones included
  int iterations = 0;  // Ipopt iterations of those solves (deterministic, unlike time_ms)
  double time_ms = 0.0;
};

class StepMotionPlanner {
 public:
  StepMotionPlanner(const Scene& scene, const SolverOptions& solver, MotionOptions options);

  // The motion from step `a` to the next step `b` of a plan (b.motion is not read).
  StepMotionResult plan(const PlanStep& a, const PlanStep& b);

  const MotionOptions& options() const { return options_; }

 private:
  // A contact of the moving link held off its surface: its placement goes from `from` to `to`
  // and its height above s2 from `h_from` to `h_to`.
  struct LinkPath {
    ContactTask task;  // unloaded
    Placement from, to;
    double h_from = 0.0, h_to = 0.0;
    double length() const;  // of the path of s1's origin (m)
    Placement placement_at(double s) const;
    LinkPath part(double s0, double s1) const;  // the path between s0 and s1, run over [0, 1]
  };

  // One piece of the path: the reference runs from q_start to q_ref_end; `end` is the fixed
  // configuration the last sample must join (nullptr: the projection at s = 1 is the last sample).
  struct Segment {
    const char* name = "";  // lift, travel or approach (in messages)
    const Eigen::VectorXd* q_start = nullptr;
    const Eigen::VectorXd* q_ref_end = nullptr;
    const Eigen::VectorXd* end = nullptr;
    // The moving link held off its surface (E9 with a standoff, E10-E13 at a placement), both
    // interpolated along s in [0, 1]; nullopt: the link is free (E20 keeps it clear).
    std::optional<LinkPath> link;
  };

  bool set_up(const PlanStep& a, const PlanStep& b, StepMotion* motion);
  void plan_segments(const PlanStep& a, const PlanStep& b, StepMotion* motion);
  std::string describe(const SpacingMeasure& m) const;
  bool run_segment(const Segment& segment, std::vector<MotionSample>* samples, StepMotion* motion);
  // q_to, at s1 (a projected sample, or the segment's fixed end), is farther than the spacing
  // from q_from (its predecessor, at s0) although the interpolation step was halved: the
  // projection jumped, or the last sample did not join the end. Joins the two by a sub-segment
  // whose reference runs from q_from to q_to (the moving link from its s0 to its s1 parameters),
  // its samples appended; false (nothing appended) when that fails too.
  bool bridge(const Segment& segment, double s0, double s1, const Eigen::VectorXd& q_from,
              const Eigen::VectorXd& q_to, std::vector<MotionSample>* samples, StepMotion* motion);
  // The secant predictor of a continuation method (Allgower & Georg, Introduction to Numerical
  // Continuation Methods, 1990): the sample before the last (q_before, its forces `before` when it
  // is a sample), and the ratio k of the next step in s to the last one. The next sample is
  // guessed on the line through the last two: q_prev + k (q_prev - q_before), forces alike.
  struct Secant {
    const Eigen::VectorXd* q_before = nullptr;
    const MotionSample* before = nullptr;
    double k = 0.0;
  };
  // Projects the sample at s of the segment, warm started from q_prev (forces from `previous`
  // when given), or from the secant's guess; with `retry`, a failed projection is solved again by
  // retry_solver_.
  PostureResult project(const Segment& segment, double s, const Eigen::VectorXd& q_prev,
                        const MotionSample* previous, bool retry, const Secant* secant = nullptr);
  // The projection of reference q_ref with the contacts request_ holds.
  PostureResult project_reference(const Eigen::VectorXd& q_ref, const Eigen::VectorXd& q_prev,
                                  const MotionSample* previous, bool retry,
                                  const Secant* secant = nullptr);
  // request_'s force guesses: `previous`'s forces, extrapolated along the secant when given.
  void guess_forces(const MotionSample* previous, const Secant* secant);
  // The straight travel from q_from to q_to failed (its samples from `first` on reach some way):
  // a detour on the stance manifold (stance_rrt.h) replaces them, the moving link free.
  bool detour(const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
              std::vector<MotionSample>* samples, size_t first, StepMotion* motion);
  ContactTask lift_task(const Contact& contact, const Eigen::VectorXd& q) const;
  // s1 straight up from its placement at q to the clearance.
  LinkPath lift_path(const Contact& contact, const Eigen::VectorXd& q) const;

  const Scene& scene_;
  PostureSolver solver_;        // warm projections: few iterations, small fixed barrier
  PostureSolver retry_solver_;  // a sample solver_ fails: adaptive barrier, more iterations
  MotionOptions options_;
  int held_ = 0;            // request_.contacts[0, held_): sigma, loaded, placements fixed
  PostureRequest request_;  // reused for every sample
  Eigen::VectorXd q_ref_;   // workspace of the interpolation
  std::optional<SampleSpacing> spacing_;  // surfaces of both steps' contacts
  int solves_ = 0;
  int iterations_ = 0;
  int bridge_depth_ = 0;
  int segment_solves_ = 0;  // solves_ when the current segment started
};

}  // namespace stanceplan
