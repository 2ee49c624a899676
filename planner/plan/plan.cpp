#include "planner/plan/plan.h"

namespace stanceplan {
namespace {
constexpr MotionStatus kMotionStatuses[] = {MotionStatus::Solved, MotionStatus::ProjectionFailed,
                                            MotionStatus::SpacingNotReached,
                                            MotionStatus::EndsDisagree};
}

const char* to_string(MotionStatus status) {
  switch (status) {
    case MotionStatus::Solved:
      return "solved";
    case MotionStatus::ProjectionFailed:
      return "projection_failed";
    case MotionStatus::SpacingNotReached:
      return "spacing_not_reached";
    case MotionStatus::EndsDisagree:
      return "ends_disagree";
  }
  return "?";
}

bool parse_motion_status(const std::string& text, MotionStatus* status) {
  for (MotionStatus s : kMotionStatuses)
    if (text == to_string(s)) {
      *status = s;
      return true;
    }
  return false;
}

}  // namespace stanceplan
