// Second and third derivatives of the kinematics (kinematics_hessian.h) against central finite
// differences of the exact first derivatives (kinematics.h), on the project's humanoid, TALOS,
// Panda (prismatic + mimic fingers), the branching test tree (every joint type, a mimic on another
// branch) and a chain where a mimic joint and its source, and a prismatic pair, act on one point.
// Floating roots use a quaternion of norm 0.8..1.2. Also: the quaternion's second derivatives,
// exact symmetry, the scale / accumulation contract and the per-link path of very large models.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "planner/model/kinematics.h"
#include "planner/model/kinematics_hessian.h"
#include "planner/model/quaternion.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/paths.h"
#include "tests/support/test_models.h"

namespace stanceplan {
namespace {

// A chain whose mimic joints share their source's column: m2 follows j1 (x1.5) one link below it,
// m4 (prismatic) follows p3 (x-0.5); the derivative with respect to the shared dof sums both.
const char* kMimicChainUrdf = R"(<robot name="mimic_chain">
  <link name="root"><inertial><mass value="2"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <link name="l1"><inertial><origin xyz="0.1 0 0.05"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="l2"><inertial><origin xyz="0 0.1 0"/><mass value="0.7"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="l3"><inertial><origin xyz="0 0 0.1"/><mass value="0.5"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="l4"><inertial><origin xyz="0.05 0 0"/><mass value="0.4"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="l5"><inertial><origin xyz="0.1 0.1 0"/><mass value="0.3"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="tip"/>
  <joint name="j1" type="revolute"><parent link="root"/><child link="l1"/>
    <origin xyz="0 0 0.1" rpy="0.2 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <joint name="m2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.2 0 0" rpy="0 0.3 0"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/>
    <mimic joint="j1" multiplier="1.5" offset="0.2"/></joint>
  <joint name="p3" type="prismatic"><parent link="l2"/><child link="l3"/>
    <origin xyz="0 0.2 0"/><axis xyz="1 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <joint name="m4" type="prismatic"><parent link="l3"/><child link="l4"/>
    <origin xyz="0 0 0.1" rpy="0 0 0.7"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
    <mimic joint="p3" multiplier="-0.5" offset="0"/></joint>
  <joint name="j5" type="continuous"><parent link="l4"/><child link="l5"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 1 0"/><limit effort="10" velocity="1"/></joint>
  <joint name="f6" type="fixed"><parent link="l5"/><child link="tip"/>
    <origin xyz="0.1 0 0.1"/></joint>
</robot>)";

UrdfOptions with_package(const std::string& dir) {
  UrdfOptions options;
  options.packages.directories = {dir};
  options.packages.use_ros_package_path = false;
  return options;
}

Entity make_entity(std::shared_ptr<const Model> model, EntityKind kind) {
  Entity e;
  e.name = model->name;
  e.kind = kind;
  e.model = std::move(model);
  if (!e.floating()) {
    e.T_WB.linear() =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    e.T_WB.translation() = Eigen::Vector3d(0.3, -0.2, 0.9);
  }
  return e;
}

// The models, loaded once per test process.
const Entity& test_entity(const std::string& name) {
  static std::map<std::string, Entity> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  const auto from_string = [](const char* urdf) {
    return std::make_shared<Model>(load_urdf_string(urdf, "."));
  };
  Entity e;
  if (name == "branching_fixed")
    e = make_entity(from_string(test::kBranchingUrdf), EntityKind::FixedRobot);
  else if (name == "branching_floating")
    e = make_entity(from_string(test::kBranchingUrdf), EntityKind::FloatingRobot);
  else if (name == "mimic_chain_floating")
    e = make_entity(from_string(kMimicChainUrdf), EntityKind::FloatingRobot);
  else if (name == "humanoid")
    e = make_entity(std::make_shared<Model>(
                        load_urdf(test::source_path("assets/robots/humanoid/humanoid.urdf"))),
                    EntityKind::FloatingRobot);
  else if (name == "talos")
    e = make_entity(std::make_shared<Model>(
                        load_urdf(test::talos_urdf(), with_package(test::talos_package_dir()))),
                    EntityKind::FloatingRobot);
  else if (name == "panda_fixed")
    e = make_entity(std::make_shared<Model>(
                        load_urdf(test::panda_urdf(), with_package(test::panda_package_dir()))),
                    EntityKind::FixedRobot);
  return cache.emplace(name, e).first->second;
}

Eigen::VectorXd random_configuration(const Entity& e, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  Eigen::VectorXd q(e.nq());
  for (int i = 0; i < q.size(); ++i) q[i] = u(rng);
  if (e.floating()) {
    // Not normalised: the normalisation's derivatives are part of what is checked.
    Eigen::Vector4d phi(u(rng), u(rng), u(rng), u(rng));
    phi *= std::uniform_real_distribution<double>(0.8, 1.2)(rng) / phi.norm();
    q.segment<4>(Entity::kBaseQuaternion) = phi;
  }
  return q;
}

Eigen::Vector3d random_vector(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Eigen::Vector3d(u(rng), u(rng), u(rng));
}

// Central differences of f(data, out) (out: `rows` values) with respect to q[columns[k]] in
// column k; every coordinate when `columns` is empty.
using Sampler = std::function<void(const ModelData&, Eigen::Ref<Eigen::VectorXd>)>;
Eigen::MatrixXd central_differences(const Entity& e, const Eigen::VectorXd& q, int rows,
                                    const Sampler& f, std::vector<int> columns = {}) {
  const double h = 1e-6;
  if (columns.empty())
    for (int i = 0; i < q.size(); ++i) columns.push_back(i);
  ModelData data(e);
  Eigen::MatrixXd D(rows, columns.size());
  Eigen::VectorXd plus(rows), minus(rows);
  for (size_t k = 0; k < columns.size(); ++k) {
    Eigen::VectorXd qp = q, qm = q;
    qp[columns[k]] += h;
    qm[columns[k]] -= h;
    forward_kinematics(e, qp, data);
    f(data, plus);
    forward_kinematics(e, qm, data);
    f(data, minus);
    D.col(k) = (plus - minus) / (2 * h);
  }
  return D;
}

// |analytic - numeric| <= 1e-6 of the numeric's scale (Frobenius, at least 1).
::testing::AssertionResult close(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  const double error = (analytic - numeric).norm();
  const double scale = std::max(1.0, numeric.norm());
  if (error <= 1e-6 * scale) return ::testing::AssertionSuccess();
  std::ostringstream out;
  out << "error " << error << " at scale " << scale << "\nanalytic\n"
      << analytic << "\nnumeric\n"
      << numeric;
  return ::testing::AssertionFailure() << out.str();
}

::testing::AssertionResult exactly_symmetric(const Eigen::MatrixXd& H) {
  const double asymmetry = (H - H.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry == 0.0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "max |H - H^T| = " << asymmetry;
}

// The joint part [0; w] of a configuration-sized vector.
Eigen::VectorXd joint_direction(const Entity& e, const Eigen::VectorXd& w) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(e.nq());
  d.tail(w.size()) = w;
  return d;
}

constexpr int kTrials = 20;
const Eigen::Vector3d kPointOnLink(0.03, -0.07, 0.11);
const Eigen::Vector3d kVectorOnLink = Eigen::Vector3d(0.2, -0.5, 0.8).normalized();

class KinematicsHessianTest : public ::testing::TestWithParam<std::string> {
 protected:
  // TALOS and the Panda come from ../shared: only their cases skip without it.
  void SetUp() override {
    if (GetParam() == "talos") STANCEPLAN_REQUIRE_SHARED("robots/talos");
    if (GetParam() == "panda_fixed") STANCEPLAN_REQUIRE_SHARED("robots/panda");
  }
  const Entity& entity() const { return test_entity(GetParam()); }
  int nq() const { return entity().nq(); }
  int num_links() const { return entity().model->num_links(); }
  Eigen::MatrixXd zero() const { return Eigen::MatrixXd::Zero(nq(), nq()); }
  Eigen::VectorXd random_rates(std::mt19937& rng) const {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd w(entity().model->num_dofs());
    for (int i = 0; i < w.size(); ++i) w[i] = u(rng);
    return w;
  }
  // The point's velocity from the first derivatives: v = J_p [0; w].
  Eigen::Vector3d velocity_from_jacobian(const ModelData& d, int link,
                                         const Eigen::VectorXd& w) const {
    Eigen::MatrixXd J(3, nq());
    point_jacobian(entity(), d, link, kPointOnLink, J);
    return J * joint_direction(entity(), w);
  }
};

TEST_P(KinematicsHessianTest, PointHessianMatchesDifferencesOfThePointJacobian) {
  const Entity& e = entity();
  std::mt19937 rng(101);
  ModelData data(e);
  Eigen::MatrixXd J(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::Vector3d c = random_vector(rng);
    // Every link at once: rows link * nq .. of the stacked gradients J^T c.
    const Eigen::MatrixXd numeric = central_differences(
        e, q, num_links() * nq(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          for (int l = 0; l < num_links(); ++l) {
            point_jacobian(e, d, l, kPointOnLink, J);
            out.segment(l * nq(), nq()) = J.transpose() * c;
          }
        });
    forward_kinematics(e, q, data);
    for (int l = 0; l < num_links(); ++l) {
      Eigen::MatrixXd H = zero();
      add_point_hessian(e, data, l, data.T_WL[l] * kPointOnLink, c, 1.0, H);
      EXPECT_TRUE(exactly_symmetric(H)) << e.model->links[l].name;
      EXPECT_TRUE(close(H, numeric.middleRows(l * nq(), nq())))
          << GetParam() << " trial " << trial << " link " << e.model->links[l].name;
    }
  }
}

TEST_P(KinematicsHessianTest, VectorHessianMatchesDifferencesOfTheVectorJacobian) {
  const Entity& e = entity();
  std::mt19937 rng(202);
  ModelData data(e);
  Eigen::MatrixXd J(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::Vector3d c = random_vector(rng);
    const Eigen::MatrixXd numeric = central_differences(
        e, q, num_links() * nq(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          for (int l = 0; l < num_links(); ++l) {
            vector_jacobian(e, d, l, kVectorOnLink, J);
            out.segment(l * nq(), nq()) = J.transpose() * c;
          }
        });
    forward_kinematics(e, q, data);
    for (int l = 0; l < num_links(); ++l) {
      Eigen::MatrixXd H = zero();
      add_vector_hessian(e, data, l, data.T_WL[l].linear() * kVectorOnLink, c, 1.0, H);
      EXPECT_TRUE(exactly_symmetric(H)) << e.model->links[l].name;
      EXPECT_TRUE(close(H, numeric.middleRows(l * nq(), nq())))
          << GetParam() << " trial " << trial << " link " << e.model->links[l].name;
    }
  }
}

TEST_P(KinematicsHessianTest, ComHessianMatchesDifferencesOfTheComJacobian) {
  const Entity& e = entity();
  std::mt19937 rng(303);
  ModelData data(e);
  Eigen::MatrixXd J(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::Vector3d c = random_vector(rng);
    const Eigen::MatrixXd numeric =
        central_differences(e, q, nq(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          center_of_mass_jacobian(e, d, J);
          out = J.transpose() * c;
        });
    forward_kinematics(e, q, data);
    Eigen::MatrixXd H = zero();
    add_com_hessian(e, data, c, 1.0, H);
    EXPECT_TRUE(exactly_symmetric(H));
    EXPECT_TRUE(close(H, numeric)) << GetParam() << " trial " << trial;
    EXPECT_GT(H.norm(), 1e-3);  // not vacuous
  }
}

TEST_P(KinematicsHessianTest, PointVelocityJacobianMatchesDifferencesOfTheVelocity) {
  const Entity& e = entity();
  std::mt19937 rng(404);
  ModelData data(e);
  Eigen::MatrixXd J_v(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::VectorXd w = random_rates(rng);
    const Eigen::MatrixXd numeric = central_differences(
        e, q, 3 * num_links(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          for (int l = 0; l < num_links(); ++l)
            out.segment<3>(3 * l) = velocity_from_jacobian(d, l, w);
        });
    forward_kinematics(e, q, data);
    for (int l = 0; l < num_links(); ++l) {
      const Eigen::Vector3d v =
          point_velocity_jacobian(e, data, l, data.T_WL[l] * kPointOnLink, w, J_v);
      EXPECT_LE((v - velocity_from_jacobian(data, l, w)).norm(), 1e-12);
      EXPECT_TRUE(close(J_v, numeric.middleRows(3 * l, 3)))
          << GetParam() << " trial " << trial << " link " << e.model->links[l].name;
    }
  }
}

TEST_P(KinematicsHessianTest, PointVelocityHessianMatchesDifferencesOfItsJacobian) {
  const Entity& e = entity();
  std::mt19937 rng(505);
  ModelData data(e);
  Eigen::MatrixXd J_v(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::VectorXd w = random_rates(rng);
    const Eigen::Vector3d c = random_vector(rng);
    const Eigen::MatrixXd numeric = central_differences(
        e, q, num_links() * nq(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          for (int l = 0; l < num_links(); ++l) {
            point_velocity_jacobian(e, d, l, d.T_WL[l] * kPointOnLink, w, J_v);
            out.segment(l * nq(), nq()) = J_v.transpose() * c;
          }
        });
    forward_kinematics(e, q, data);
    for (int l = 0; l < num_links(); ++l) {
      Eigen::MatrixXd H = zero();
      add_point_velocity_hessian(e, data, l, data.T_WL[l] * kPointOnLink, w, c, 1.0, H);
      EXPECT_TRUE(exactly_symmetric(H)) << e.model->links[l].name;
      EXPECT_TRUE(close(H, numeric.middleRows(l * nq(), nq())))
          << GetParam() << " trial " << trial << " link " << e.model->links[l].name;
    }
  }
}

// Independent of point_velocity_jacobian: v = d p(q + s [0; w]) / ds, so the velocity's Hessian
// is the point Hessian's derivative along [0; w].
TEST_P(KinematicsHessianTest, PointVelocityHessianIsThePointHessiansRateAlongW) {
  const Entity& e = entity();
  std::mt19937 rng(606);
  ModelData data(e), moved(e);
  for (int trial = 0; trial < kTrials / 4; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::VectorXd w = random_rates(rng);
    const Eigen::VectorXd dq = joint_direction(e, w);
    const Eigen::Vector3d c = random_vector(rng);
    const double h = 1e-6;
    forward_kinematics(e, q, data);
    for (int l = 0; l < num_links(); ++l) {
      Eigen::MatrixXd plus = zero(), minus = zero(), H = zero();
      forward_kinematics(e, q + h * dq, moved);
      add_point_hessian(e, moved, l, moved.T_WL[l] * kPointOnLink, c, 1.0, plus);
      forward_kinematics(e, q - h * dq, moved);
      add_point_hessian(e, moved, l, moved.T_WL[l] * kPointOnLink, c, 1.0, minus);
      add_point_velocity_hessian(e, data, l, data.T_WL[l] * kPointOnLink, w, c, 1.0, H);
      EXPECT_TRUE(close(H, (plus - minus) / (2 * h)))
          << GetParam() << " trial " << trial << " link " << e.model->links[l].name;
    }
  }
}

TEST_P(KinematicsHessianTest, ComVelocityJacobianAndHessianMatchDifferences) {
  const Entity& e = entity();
  std::mt19937 rng(707);
  ModelData data(e);
  Eigen::MatrixXd J(3, nq()), J_v(3, nq());
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::VectorXd q = random_configuration(e, rng);
    const Eigen::VectorXd w = random_rates(rng);
    const Eigen::VectorXd dq = joint_direction(e, w);
    const Eigen::Vector3d c = random_vector(rng);
    // [v_C; J_v^T c] from the first derivatives and from com_velocity_jacobian.
    const Eigen::MatrixXd numeric = central_differences(
        e, q, 3 + nq(), [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
          center_of_mass_jacobian(e, d, J);
          out.head(3) = J * dq;
          com_velocity_jacobian(e, d, w, J_v);
          out.tail(nq()) = J_v.transpose() * c;
        });
    forward_kinematics(e, q, data);
    center_of_mass_jacobian(e, data, J);
    const Eigen::Vector3d v_C = com_velocity_jacobian(e, data, w, J_v);
    EXPECT_LE((v_C - J * dq).norm(), 1e-12);
    EXPECT_TRUE(close(J_v, numeric.topRows(3))) << GetParam() << " trial " << trial;
    Eigen::MatrixXd H = zero();
    add_com_velocity_hessian(e, data, w, c, 1.0, H);
    EXPECT_TRUE(exactly_symmetric(H));
    EXPECT_TRUE(close(H, numeric.bottomRows(nq()))) << GetParam() << " trial " << trial;
    // And as the CoM Hessian's rate along [0; w].
    const double h = 1e-6;
    ModelData moved(e);
    Eigen::MatrixXd plus = zero(), minus = zero();
    forward_kinematics(e, q + h * dq, moved);
    add_com_hessian(e, moved, c, 1.0, plus);
    forward_kinematics(e, q - h * dq, moved);
    add_com_hessian(e, moved, c, 1.0, minus);
    EXPECT_TRUE(close(H, (plus - minus) / (2 * h))) << GetParam() << " trial " << trial;
  }
}

// Every H is added to, scaled: two calls at 0.5 give one call at 1, a call onto a filled H adds.
TEST_P(KinematicsHessianTest, HessiansAreScaledAndAccumulated) {
  const Entity& e = entity();
  std::mt19937 rng(808);
  const Eigen::VectorXd q = random_configuration(e, rng);
  const Eigen::VectorXd w = random_rates(rng);
  const Eigen::Vector3d c = random_vector(rng);
  ModelData data(e);
  forward_kinematics(e, q, data);
  const int link = num_links() - 1;
  const Eigen::Vector3d p = data.T_WL[link] * kPointOnLink;
  const Eigen::Vector3d v = data.T_WL[link].linear() * kVectorOnLink;
  const std::map<std::string, std::function<void(double, Eigen::MatrixXd&)>> functions = {
      {"point",
       [&](double s, Eigen::MatrixXd& H) { add_point_hessian(e, data, link, p, c, s, H); }},
      {"vector",
       [&](double s, Eigen::MatrixXd& H) { add_vector_hessian(e, data, link, v, c, s, H); }},
      {"point velocity",
       [&](double s, Eigen::MatrixXd& H) {
         add_point_velocity_hessian(e, data, link, p, w, c, s, H);
       }},
      {"com", [&](double s, Eigen::MatrixXd& H) { add_com_hessian(e, data, c, s, H); }},
      {"com velocity",
       [&](double s, Eigen::MatrixXd& H) { add_com_velocity_hessian(e, data, w, c, s, H); }},
  };
  for (const auto& [name, add] : functions) {
    Eigen::MatrixXd once = zero(), halves = zero();
    add(1.0, once);
    ASSERT_GT(once.norm(), 1e-6) << name;
    add(0.5, halves);
    add(0.5, halves);
    EXPECT_LE((halves - once).norm(), 1e-14 * once.norm()) << name;
    Eigen::MatrixXd twice = once;
    add(1.0, twice);
    EXPECT_LE((twice - 2 * once).norm(), 1e-14 * once.norm()) << name;
    Eigen::MatrixXd negated = once;
    add(-3.0, negated);
    EXPECT_LE((negated + 2 * once).norm(), 1e-14 * once.norm()) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Models, KinematicsHessianTest,
                         ::testing::Values("branching_fixed", "branching_floating",
                                           "mimic_chain_floating", "humanoid", "talos",
                                           "panda_fixed"),
                         [](const auto& info) { return info.param; });

// ---------------------------------------------------------------------------------------------

TEST(KinematicsHessianModels, TestModelsHaveTheJointsTheyAreMeantToExercise) {
  const Model& chain = *test_entity("mimic_chain_floating").model;
  EXPECT_EQ(chain.num_dofs(), 3);  // j1, p3, j5; m2 and m4 share j1's and p3's columns
  EXPECT_EQ(chain.joints[chain.find_joint("m2")].dof, chain.find_dof("j1"));
  EXPECT_EQ(chain.joints[chain.find_joint("m4")].dof, chain.find_dof("p3"));
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const Model& panda = *test_entity("panda_fixed").model;
  EXPECT_TRUE(panda.joints[panda.find_joint("panda_finger_joint2")].is_mimic);
  EXPECT_EQ(panda.joints[panda.find_joint("panda_finger_joint1")].type, JointType::Prismatic);
}

TEST(QuaternionSecondDerivatives, MatchDifferencesOfTheFirstDerivatives) {
  std::mt19937 rng(909);
  std::uniform_real_distribution<double> u(-1.0, 1.0), norm(0.8, 1.2);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Vector4d phi(u(rng), u(rng), u(rng), u(rng));
    phi *= norm(rng) / phi.norm();
    std::array<std::array<Eigen::Matrix3d, 4>, 4> d2R;
    rotation_quaternion_second_derivatives(phi, &d2R);
    const double h = 1e-6;
    for (int b = 0; b < 4; ++b) {
      std::array<Eigen::Matrix3d, 4> plus, minus;
      rotation_quaternion_derivatives(phi + h * Eigen::Vector4d::Unit(b), &plus);
      rotation_quaternion_derivatives(phi - h * Eigen::Vector4d::Unit(b), &minus);
      for (int a = 0; a < 4; ++a) {
        EXPECT_TRUE(close(d2R[a][b], (plus[a] - minus[a]) / (2 * h)))
            << "a " << a << " b " << b << " phi " << phi.transpose();
        EXPECT_EQ((d2R[a][b] - d2R[b][a]).norm(), 0.0);
      }
    }
    // The radial direction changes nothing: R(s phi) = R(phi) for s > 0, so its second
    // derivative in s, sum_ab phi_a phi_b d2R_ab, vanishes.
    Eigen::Matrix3d radial = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) radial += phi[a] * phi[b] * d2R[a][b];
    EXPECT_LE(radial.norm(), 1e-12);
  }
}

TEST(QuaternionSecondDerivatives, BilinearHessianIsTheContractedMatrices) {
  std::mt19937 rng(1001);
  std::uniform_real_distribution<double> u(-1.0, 1.0), norm(0.8, 1.2);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Vector4d phi(u(rng), u(rng), u(rng), u(rng));
    phi *= norm(rng) / phi.norm();
    const Eigen::Vector3d c = random_vector(rng), x = random_vector(rng);
    std::array<std::array<Eigen::Matrix3d, 4>, 4> d2R;
    rotation_quaternion_second_derivatives(phi, &d2R);
    Eigen::Matrix4d expected;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) expected(a, b) = c.dot(d2R[a][b] * x);
    const Eigen::Matrix4d H = rotation_bilinear_hessian(phi, c, x);
    EXPECT_LE((H - expected).norm(), 1e-12 * std::max(1.0, expected.norm()));
    EXPECT_EQ((H - H.transpose()).norm(), 0.0);
  }
}

// A chain longer than the subtree workspace (256 links): the centre of mass's velocity terms take
// the per-link path and still match the differences.
TEST(KinematicsHessianLargeModel, ComVelocityOfA300LinkChainMatchesDifferences) {
  std::ostringstream urdf;
  urdf << "<robot name=\"long\">";
  const int n = 300;
  for (int i = 0; i < n; ++i)
    urdf << "<link name=\"l" << i << "\"><inertial><origin xyz=\"0.01 0 0.005\"/><mass value=\""
         << 0.1 + 0.001 * (i % 7)
         << "\"/><inertia ixx=\"0.001\" ixy=\"0\" ixz=\"0\" iyy=\"0.001\" iyz=\"0\" "
            "izz=\"0.001\"/></inertial></link>";
  for (int i = 1; i < n; ++i)
    urdf << "<joint name=\"j" << i << "\" type=\"" << (i % 11 == 0 ? "prismatic" : "revolute")
         << "\"><parent link=\"l" << i - 1 << "\"/><child link=\"l" << i
         << "\"/><origin xyz=\"0.02 0 0\"/><axis xyz=\"" << (i % 3 == 0) << " " << (i % 3 == 1)
         << " " << (i % 3 == 2)
         << "\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>";
  urdf << "</robot>";
  const Entity e = make_entity(std::make_shared<Model>(load_urdf_string(urdf.str(), ".")),
                               EntityKind::FloatingRobot);
  ASSERT_EQ(e.model->num_links(), n);
  std::mt19937 rng(1102);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::VectorXd q = random_configuration(e, rng);
  for (int i = e.first_dof(); i < e.nq(); ++i) q[i] = u(rng);
  Eigen::VectorXd w(e.model->num_dofs());
  for (int i = 0; i < w.size(); ++i) w[i] = u(rng);
  const Eigen::VectorXd dq = joint_direction(e, w);
  const Eigen::Vector3d c = random_vector(rng);
  Eigen::MatrixXd J(3, e.nq()), J_v(3, e.nq());
  // The root's coordinates and every 13th joint (the per-link path is slow to difference).
  std::vector<int> columns = {0, 1, 2, 3, 4, 5, 6};
  for (int i = e.first_dof(); i < e.nq(); i += 13) columns.push_back(i);
  const Eigen::MatrixXd numeric = central_differences(
      e, q, 3 + e.nq(),
      [&](const ModelData& d, Eigen::Ref<Eigen::VectorXd> out) {
        center_of_mass_jacobian(e, d, J);
        out.head(3) = J * dq;
        com_velocity_jacobian(e, d, w, J_v);
        out.tail(e.nq()) = J_v.transpose() * c;
      },
      columns);
  ModelData data(e);
  forward_kinematics(e, q, data);
  center_of_mass_jacobian(e, data, J);
  EXPECT_LE((com_velocity_jacobian(e, data, w, J_v) - J * dq).norm(), 1e-12);
  EXPECT_TRUE(close(J_v(Eigen::all, columns), numeric.topRows(3)));
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(e.nq(), e.nq());
  add_com_velocity_hessian(e, data, w, c, 1.0, H);
  EXPECT_TRUE(exactly_symmetric(H));
  EXPECT_TRUE(close(H(Eigen::all, columns), numeric.bottomRows(e.nq())));
}

}  // namespace
}  // namespace stanceplan
