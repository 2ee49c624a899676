// Forward kinematics against hand-computed poses, and every Jacobian (point, vector, centre of
// mass; fixed and floating base; quaternion root) against central finite differences.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>

#include "planner/model/kinematics.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/test_models.h"

namespace stanceplan {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Two unit links rotating about z, the first joint 0.5 m above the root.
const char* kPlanarArm = R"(<robot name="planar">
  <link name="root"/>
  <link name="l1"><inertial><origin xyz="0.5 0 0"/><mass value="2"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <link name="l2"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="q1" type="revolute"><parent link="root"/><child link="l1"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="q2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>)";

Entity make_entity(const char* urdf, EntityKind kind) {
  Entity e;
  e.name = "e";
  e.kind = kind;
  e.model = std::make_shared<Model>(load_urdf_string(urdf, "."));
  return e;
}

TEST(ForwardKinematics, PlanarArmFixedBaseMatchesHandComputedPose) {
  Entity arm = make_entity(kPlanarArm, EntityKind::FixedRobot);
  arm.T_WB.translation() = Eigen::Vector3d(1.0, 2.0, 0.0);
  ModelData data(arm);
  const double q1 = 0.3, q2 = -1.1;
  forward_kinematics(arm, Eigen::Vector2d(q1, q2), data);
  const int l2 = arm.model->find_link("l2");
  const Eigen::Vector3d expected_origin(1.0 + std::cos(q1), 2.0 + std::sin(q1), 0.5);
  EXPECT_NEAR((data.T_WL[l2].translation() - expected_origin).norm(), 0.0, 1e-12);
  const Eigen::Vector3d tip = data.T_WL[l2] * Eigen::Vector3d(1, 0, 0);
  const Eigen::Vector3d expected_tip(1.0 + std::cos(q1) + std::cos(q1 + q2),
                                     2.0 + std::sin(q1) + std::sin(q1 + q2), 0.5);
  EXPECT_NEAR((tip - expected_tip).norm(), 0.0, 1e-12);
  // Centre of mass: (2 * mid of link 1 + 1 * mid of link 2) / 3.
  const Eigen::Vector3d c1(1.0 + 0.5 * std::cos(q1), 2.0 + 0.5 * std::sin(q1), 0.5);
  const Eigen::Vector3d c2(1.0 + std::cos(q1) + 0.5 * std::cos(q1 + q2),
                           2.0 + std::sin(q1) + 0.5 * std::sin(q1 + q2), 0.5);
  EXPECT_NEAR((center_of_mass(arm, data) - (2 * c1 + c2) / 3).norm(), 0.0, 1e-12);
}

TEST(ForwardKinematics, PlanarArmFloatingBaseMatchesHandComputedPose) {
  Entity arm = make_entity(kPlanarArm, EntityKind::FloatingRobot);
  ModelData data(arm);
  Eigen::VectorXd q(9);
  // Root at (0, 0, 1) turned by 90 degrees about x: the arm's z axis becomes -y.
  const double c = std::cos(kPi / 4), s = std::sin(kPi / 4);
  q << 0, 0, 1, c, s, 0, 0, kPi / 2, 0;
  forward_kinematics(arm, q, data);
  const int l2 = arm.model->find_link("l2");
  // Joint 1 at root + R_x(90) (0, 0, 0.5) = (0, -0.5, 1); link 1 along R_x(90) R_z(90) x = z.
  const Eigen::Vector3d expected(0.0, -0.5, 2.0);
  EXPECT_NEAR((data.T_WL[l2].translation() - expected).norm(), 0.0, 1e-12);
  // A non-unit quaternion gives the same pose: R(phi) uses phi / |phi|.
  q.segment<4>(3) *= 3.0;
  forward_kinematics(arm, q, data);
  EXPECT_NEAR((data.T_WL[l2].translation() - expected).norm(), 0.0, 1e-12);
}

TEST(ForwardKinematics, MimicJointFollowsItsSource) {
  Entity e = make_entity(test::kBranchingUrdf, EntityKind::FixedRobot);
  ModelData data(e);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(e.nq());
  q[e.model->find_dof("j1")] = 0.4;
  forward_kinematics(e, q, data);
  EXPECT_EQ(e.model->num_dofs(), 5);  // m7 is not a dof
  EXPECT_NEAR(data.joint_position[e.model->find_joint("m7")], -2 * 0.4 + 0.1, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Finite-difference checks.

class JacobianTest : public ::testing::TestWithParam<EntityKind> {
 protected:
  void SetUp() override {
    entity_ = make_entity(test::kBranchingUrdf, GetParam());
    if (GetParam() == EntityKind::FixedRobot) {
      entity_.T_WB.linear() =
          Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      entity_.T_WB.translation() = Eigen::Vector3d(0.3, -0.2, 0.9);
    }
  }

  Eigen::VectorXd random_configuration(std::mt19937& rng) const {
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    Eigen::VectorXd q(entity_.nq());
    for (int i = 0; i < q.size(); ++i) q[i] = u(rng);
    if (entity_.floating()) {
      // A quaternion of norm != 1 exercises the normalisation's derivative too.
      q.segment<4>(Entity::kBaseQuaternion) = Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng));
      q.segment<4>(Entity::kBaseQuaternion) *= 1.3 / q.segment<4>(Entity::kBaseQuaternion).norm();
    }
    return q;
  }

  // Central differences of f: q -> R^3, step h; the result is 3 x nq.
  template <class F>
  Eigen::MatrixXd numeric(const Eigen::VectorXd& q, F f, double h = 1e-6) const {
    Eigen::MatrixXd J(3, q.size());
    ModelData data(entity_);
    for (int i = 0; i < q.size(); ++i) {
      Eigen::VectorXd qp = q, qm = q;
      qp[i] += h;
      qm[i] -= h;
      forward_kinematics(entity_, qp, data);
      const Eigen::Vector3d fp = f(data);
      forward_kinematics(entity_, qm, data);
      J.col(i) = (fp - f(data)) / (2 * h);
    }
    return J;
  }

  static void expect_close(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric,
                           const std::string& what) {
    const double scale = std::max(1.0, numeric.norm());
    EXPECT_LE((analytic - numeric).norm() / scale, 1e-6) << what << "\nanalytic\n"
                                                         << analytic << "\nnumeric\n"
                                                         << numeric;
  }

  Entity entity_;
};

TEST_P(JacobianTest, PointJacobianMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  ModelData data(entity_);
  Eigen::MatrixXd J(3, entity_.nq());
  const Eigen::Vector3d p_L(0.03, -0.07, 0.11);
  for (int trial = 0; trial < 25; ++trial) {
    const Eigen::VectorXd q = random_configuration(rng);
    for (int link = 0; link < entity_.model->num_links(); ++link) {
      forward_kinematics(entity_, q, data);
      point_jacobian(entity_, data, link, p_L, J);
      const auto f = [&](const ModelData& d) -> Eigen::Vector3d { return d.T_WL[link] * p_L; };
      expect_close(J, numeric(q, f), "link " + entity_.model->links[link].name);
    }
  }
}

TEST_P(JacobianTest, VectorJacobianMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  ModelData data(entity_);
  Eigen::MatrixXd J(3, entity_.nq());
  const Eigen::Vector3d v_L = Eigen::Vector3d(0.2, -0.5, 0.8).normalized();
  for (int trial = 0; trial < 25; ++trial) {
    const Eigen::VectorXd q = random_configuration(rng);
    for (int link = 0; link < entity_.model->num_links(); ++link) {
      forward_kinematics(entity_, q, data);
      vector_jacobian(entity_, data, link, v_L, J);
      const auto f = [&](const ModelData& d) -> Eigen::Vector3d {
        return d.T_WL[link].linear() * v_L;
      };
      expect_close(J, numeric(q, f), "link " + entity_.model->links[link].name);
    }
  }
}

TEST_P(JacobianTest, CenterOfMassJacobianMatchesFiniteDifferences) {
  std::mt19937 rng(13);
  ModelData data(entity_);
  Eigen::MatrixXd J(3, entity_.nq());
  for (int trial = 0; trial < 25; ++trial) {
    const Eigen::VectorXd q = random_configuration(rng);
    forward_kinematics(entity_, q, data);
    center_of_mass_jacobian(entity_, data, J);
    const auto f = [&](const ModelData& d) -> Eigen::Vector3d {
      return center_of_mass(entity_, d);
    };
    expect_close(J, numeric(q, f), "centre of mass");
  }
}

TEST_P(JacobianTest, RepeatedCallsGiveBitwiseIdenticalResults) {
  std::mt19937 rng(17);
  const Eigen::VectorXd q = random_configuration(rng);
  ModelData data(entity_);
  Eigen::MatrixXd first(3, entity_.nq()), again(3, entity_.nq());
  forward_kinematics(entity_, q, data);
  center_of_mass_jacobian(entity_, data, first);
  for (int i = 0; i < 20; ++i) {
    forward_kinematics(entity_, q, data);
    center_of_mass_jacobian(entity_, data, again);
    ASSERT_EQ(0, std::memcmp(first.data(), again.data(), sizeof(double) * first.size()));
  }
}

INSTANTIATE_TEST_SUITE_P(FixedAndFloating, JacobianTest,
                         ::testing::Values(EntityKind::FixedRobot, EntityKind::FloatingRobot),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace stanceplan
