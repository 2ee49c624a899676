// The kinematics the solver calls in its callbacks allocate nothing once the workspace exists
// (the model/data split): forward kinematics, point / vector / centre-of-mass Jacobians.
#include <gtest/gtest.h>

#include <memory>

#include "planner/model/kinematics.h"
#include "planner/model/kinematics_hessian.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/allocation_counter.h"
#include "tests/support/test_models.h"

namespace stanceplan {
namespace {

TEST(Kinematics, CallbacksDoNotAllocate) {
  if (!test::kCountsAllocations) GTEST_SKIP() << "malloc belongs to the sanitizer in this build";
  Entity e;
  e.name = "e";
  e.kind = EntityKind::FloatingRobot;
  e.model = std::make_shared<Model>(load_urdf_string(test::kBranchingUrdf, "."));
  ModelData data(e);
  Eigen::VectorXd q = Eigen::VectorXd::Constant(e.nq(), 0.3);
  Eigen::MatrixXd J(3, e.nq());
  const Eigen::Vector3d p(0.1, 0.2, 0.3);
  const long before = test::allocations();
  for (int i = 0; i < 10; ++i) {
    q[7] += 0.01;
    forward_kinematics(e, q, data);
    for (int link = 0; link < e.model->num_links(); ++link) {
      point_jacobian(e, data, link, p, J);
      vector_jacobian(e, data, link, p, J);
    }
    center_of_mass_jacobian(e, data, J);
  }
  EXPECT_EQ(test::allocations() - before, 0);
  // The counter itself works: a vector allocates.
  const long check = test::allocations();
  auto* v = new std::vector<double>(100);
  EXPECT_GT(test::allocations(), check);
  delete v;
}

// The analytic Hessian's kinematic terms (kinematics_hessian.h) likewise, into blocks of H.
TEST(KinematicsHessian, CallbacksDoNotAllocate) {
  if (!test::kCountsAllocations) GTEST_SKIP() << "malloc belongs to the sanitizer in this build";
  Entity e;
  e.name = "e";
  e.kind = EntityKind::FloatingRobot;
  e.model = std::make_shared<Model>(load_urdf_string(test::kBranchingUrdf, "."));
  ModelData data(e);
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(e.nq(), 0.3);
  const Eigen::VectorXd w = Eigen::VectorXd::Constant(e.model->num_dofs(), 0.2);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(e.nq() + 5, e.nq() + 5), J(3, e.nq());
  const Eigen::Vector3d p(0.1, 0.2, 0.3), c(0.5, -0.4, 0.2);
  forward_kinematics(e, q, data);
  const long before = test::allocations();
  for (int link = 0; link < e.model->num_links(); ++link) {
    auto block = H.block(2, 3, e.nq(), e.nq());
    add_point_hessian(e, data, link, p, c, 1.0, block);
    add_vector_hessian(e, data, link, p, c, 1.0, block);
    point_velocity_jacobian(e, data, link, p, w, J);
    add_point_velocity_hessian(e, data, link, p, w, c, 1.0, block);
  }
  add_com_hessian(e, data, c, 1.0, H.block(2, 3, e.nq(), e.nq()));
  com_velocity_jacobian(e, data, w, J);
  add_com_velocity_hessian(e, data, w, c, 1.0, H.block(2, 3, e.nq(), e.nq()));
  EXPECT_EQ(test::allocations() - before, 0);
  EXPECT_GT(H.norm(), 0.0);
}

}  // namespace
}  // namespace stanceplan
