#pragma once
// Candidates that failed their first attempt (from the node's configuration), remembered by what
// decided their failure: the change of
// contact, the stance it was tried from, the joint angles (the posture) and where the changed
// surface stood relative to its partner. A candidate met again in the same situation (a robot that
// walks on meets "knee on the floor" from the same standing posture at every step) is deferred by
// the search to backtracking instead of being solved at once (SearchOptions::
// defer_repeated_failures). A heuristic: the environment away from the two surfaces may differ,
// so nothing is pruned, only ordered.
#include <Eigen/Geometry>
#include <vector>

#include "planner/model/model_data.h"
#include "planner/scene/scene.h"
#include "planner/search/candidates.h"

namespace stanceplan {

class FailureMemo {
 public:
  // The neighbourhood of a remembered failure.
  static constexpr double kJointRadius = 0.3;   // rad (or m), every joint
  static constexpr double kPlaceRadius = 0.05;  // m: height above s2's plane, distance outside it
  static constexpr double kTiltRadius = 0.1;    // rad: angle between the normals

  // `data`: kinematics at `q`, the configuration the candidate was tried from.
  void record(const Scene& scene, const std::vector<ModelData>& data, const Eigen::VectorXd& q,
              const Stance& stance, const Candidate& candidate);
  bool seen(const Scene& scene, const std::vector<ModelData>& data, const Eigen::VectorXd& q,
            const Stance& stance, const Candidate& candidate) const;
  size_t size() const { return entries_.size(); }

 private:
  // Where s1 stands relative to s2.
  struct Relation {
    double height = 0.0;   // of s1's origin above s2's plane
    double outside = 0.0;  // of its projection from s2's polygon (0 inside)
    double tilt = 0.0;     // angle between s1's normal and the opposite of s2's
  };
  struct Entry {
    Candidate candidate;
    Stance stance;
    Eigen::VectorXd joints;
    Relation relation;
  };
  static Relation relation(const Scene& scene, const std::vector<ModelData>& data,
                           const Contact& c);
  std::vector<Entry> entries_;
};

}  // namespace stanceplan
