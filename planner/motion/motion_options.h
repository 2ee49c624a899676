#pragma once
// Options of the motion between two plan steps (docs/METHOD.md section 7, "Motion between
// stances"): how far apart consecutive samples may be, and how far a link that makes or breaks a
// contact rises from its surface before it travels.
#include <string>

#include "planner/motion/stance_rrt_options.h"

namespace stanceplan {

struct MotionOptions {
  // Consecutive samples: no point of a contact surface moves more than point_spacing (m), no joint
  // more than joint_spacing (rad, or m for a prismatic joint). `certify` checks these defaults.
  double point_spacing = 0.01;
  double joint_spacing = 0.05;
  // A link that breaks (makes) a contact leaves (approaches) its surface along the normal over this
  // height before (after) it travels (m).
  double clearance = 0.03;
  // E22's weight in the motion's projections, as a multiple of the plan's w_configuration: high,
  // so that each sample follows its interpolated reference and E23-E24 (forces, torques, weight
  // 1e-5) do not pull it towards another posture (the last sample would then not join the step).
  double reference_weight = 1000.0;
  // The interpolation step is halved at most this many times for one sample (a projection that
  // fails or lands too far from its predecessor) before the motion fails.
  int max_halvings = 6;
  // At most this many samples per step.
  int max_samples = 2000;
  // At most this many projections per segment of a step (lift, travel, approach; failed ones,
  // retries and bridges included): one that needs more fails with that reason.
  int max_solves = 300;
  // The detour on the stance manifold tried when the straight travel fails (stance_rrt.h).
  StanceRrtOptions detour;
};

// "" when the options are usable, else what is wrong ("clearance: expected >= 0, found -1").
std::string check_motion_options(const MotionOptions& options);

}  // namespace stanceplan
