#pragma once
// A small system for the collision tests: a fixed-base 4-joint arm (box, cylinder, sphere and
// convex-mesh links), a floating-base two-link body (box torso, convex limb) with a quaternion
// root, and an environment floor. The convex mesh is an irregular octahedron written to a temporary
// OBJ.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "planner/collision/collision_model.h"
#include "planner/collision/signed_distance.h"
#include "planner/model/kinematics.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/paths.h"

namespace stanceplan::test {

// Irregular octahedron (half-axes 0.05, 0.04, 0.07, slightly skewed), faces counter-clockwise seen
// from outside.
inline std::string write_octahedron_obj() {
  const std::filesystem::path dir = test::temp_dir("collision");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "octahedron.obj").string();
  std::ofstream out(path);
  out << "v 0.05 0.003 0\nv -0.045 0 0.004\nv 0.002 0.04 0\nv 0 -0.038 0.003\n"
         "v 0.004 0 0.07\nv 0 0.005 -0.065\n"
         "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
  return path;
}

inline std::string arm_urdf(const std::string& mesh) {
  return R"(<robot name="arm">
  <link name="base"/>
  <link name="upper"><collision><origin xyz="0 0 0.15"/>
    <geometry><box size="0.08 0.1 0.3"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0.15 0 0" rpy="0 1.5707963 0"/>
    <geometry><cylinder radius="0.04" length="0.3"/></geometry></collision></link>
  <link name="hand"><collision><origin xyz="0.02 0 0"/>
    <geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="finger"><collision><origin xyz="0.04 0 0" rpy="0.3 0.2 0.1"/>
    <geometry><mesh filename=")" +
         mesh + R"("/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j3" type="revolute"><parent link="fore"/><child link="hand"/>
    <origin xyz="0.3 0 0"/><axis xyz="1 0 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j4" type="revolute"><parent link="hand"/><child link="finger"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0.6 0.8"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>)";
}

inline std::string body_urdf(const std::string& mesh) {
  return R"(<robot name="body">
  <link name="torso"><collision><geometry><box size="0.2 0.15 0.25"/></geometry></collision></link>
  <link name="limb"><collision><origin xyz="0 0.01 0.1" rpy="0.2 -0.4 0.7"/>
    <geometry><mesh filename=")" +
         mesh + R"(" scale="1.2 -1 1.1"/></geometry></collision></link>
  <joint name="k1" type="revolute"><parent link="torso"/><child link="limb"/>
    <origin xyz="0 0 0.125"/><axis xyz="1 0 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>)";
}

inline const char* kFloorUrdf = R"(<robot name="floor">
  <link name="ground"><collision><origin xyz="0 0 -0.05"/>
    <geometry><box size="4 4 0.1"/></geometry></collision></link>
</robot>)";

inline std::shared_ptr<Model> model_from(const std::string& urdf) {
  return std::make_shared<Model>(load_urdf_string(urdf, "."));
}

struct Scene {
  System system;
  std::unique_ptr<CollisionModel> model;
  std::unique_ptr<CollisionData> work;
  std::vector<ModelData> data;
  int arm = -1, body = -1, floor = -1;

  explicit Scene(const CollisionOptions& options = {}) {
    const std::string mesh = write_octahedron_obj();
    floor = system.add(Entity{"floor", EntityKind::Environment, model_from(kFloorUrdf),
                              Eigen::Isometry3d::Identity()});
    Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
    T_WB.translation() = Eigen::Vector3d(0.0, 0.0, 0.02);
    arm = system.add(Entity{"arm", EntityKind::FixedRobot, model_from(arm_urdf(mesh)), T_WB});
    body = system.add(Entity{"body", EntityKind::FloatingRobot, model_from(body_urdf(mesh)),
                             Eigen::Isometry3d::Identity()});
    model = std::make_unique<CollisionModel>(system, options);
    work = std::make_unique<CollisionData>(system, *model);
    for (const Entity& e : system.entities()) data.emplace_back(e);
  }

  void set(const Eigen::VectorXd& q) {
    for (int e = 0; e < system.num_entities(); ++e) {
      forward_kinematics(system.entity(e), q.segment(system.offset(e), system.entity(e).nq()),
                         data[e]);
    }
    work->update(*model, data);
  }

  DistanceResult distance(const Eigen::VectorXd& q, int pair) {
    set(q);
    return signed_distance(*model, *work, pair);
  }

  int pair(int entity_a, const std::string& link_a, int entity_b, const std::string& link_b) const {
    return model->find_pair(entity_a, system.entity(entity_a).model->find_link(link_a), entity_b,
                            system.entity(entity_b).model->find_link(link_b));
  }

  // A generic configuration: arm joints away from symmetric poses, body turned by a generic unit
  // quaternion.
  Eigen::VectorXd generic_configuration() const {
    Eigen::VectorXd q = system.neutral_configuration();
    q.segment(system.offset(arm), 4) << 0.3, 0.7, -0.4, 0.5;
    Eigen::Vector4d quat(0.9, 0.2, -0.3, 0.25);
    q.segment(system.offset(body), 3) << 0.5, 0.1, 0.6;
    q.segment<4>(system.offset(body) + Entity::kBaseQuaternion) = quat.normalized();
    q[system.offset(body) + 7] = -0.6;
    return q;
  }
};

// Bisection of a scalar parameter s in [lo, hi] such that f(s) = target (f continuous, f(lo) and
// f(hi) on either side of target).
inline double solve_for(const std::function<double(double)>& f, double lo, double hi,
                        double target) {
  double f_lo = f(lo) - target;
  for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double f_mid = f(mid) - target;
    if ((f_mid < 0) == (f_lo < 0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace stanceplan::test
