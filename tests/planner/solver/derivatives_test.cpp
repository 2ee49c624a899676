// Every constraint family's Jacobian and the objective's gradient against central finite
// differences at 20 random points per program, and every nonzero inside the declared sparsity.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "planner/io/scenario.h"
#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"
#include "tests/support/point_tips.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

struct Program {
  std::string name;
  PostureRequest request;
  bool all_pairs = false;  // put every collision pair in the program (penetrating ones included)
  const Scene* scene = nullptr;  // nullptr: the humanoid before the wall
};

class Derivatives : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("wall")); }
  static void TearDownTestSuite() { delete scene_; }

  Eigen::VectorXd random_x(PostureNlp& nlp, std::mt19937& rng, const Eigen::VectorXd& q0) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd x(nlp.n());
    nlp.starting_point(x.data());
    for (int i = 0; i < q0.size(); ++i) x[i] = q0[i] + 0.3 * u(rng);
    for (int i = q0.size(); i < nlp.n(); ++i) x[i] = 20.0 * (1.0 + u(rng));
    return x;
  }

  void check(const Program& program) {
    const Scene& scene = program.scene ? *program.scene : *scene_;
    SolverOptions options;
    options.w_torque = 1e-4;
    options.w_force = 1e-3;
    std::vector<int> pairs;
    if (program.all_pairs) {
      PostureSolver solver(scene, options);
      const auto excluded = solver.excluded_pairs(program.request);
      for (size_t p = 0; p < excluded.size(); ++p)
        if (!excluded[p]) pairs.push_back(int(p));
    }
    PostureNlp nlp(scene, program.request, options, pairs);
    std::vector<int> rows(nlp.nnz()), cols(nlp.nnz());
    nlp.structure(rows.data(), cols.data());
    std::set<std::pair<int, int>> declared;
    for (int k = 0; k < nlp.nnz(); ++k) declared.insert({rows[k], cols[k]});
    if (program.all_pairs) {  // the program must really contain penetrating pairs
      Eigen::VectorXd x0(nlp.n()), g0(nlp.m());
      nlp.starting_point(x0.data());
      nlp.constraints(x0.data(), true, g0.data());
      const int b = static_cast<int>(nlp.blocks().size()) - 1;
      ASSERT_EQ(nlp.blocks()[b]->family(), "collision");
      EXPECT_LT(g0.segment(nlp.block_first_row(b), nlp.blocks()[b]->rows()).minCoeff(), -0.01);
    }
    std::mt19937 rng(42);
    const double h = 1e-6;
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd x = random_x(nlp, rng, program.request.q_init);
      const Eigen::MatrixXd J = nlp.dense_jacobian(x.data(), true);
      Eigen::VectorXd grad(nlp.n());
      nlp.objective_gradient(x.data(), false, grad.data());
      Eigen::MatrixXd J_fd(nlp.m(), nlp.n());
      Eigen::VectorXd grad_fd(nlp.n()), gp(nlp.m()), gm(nlp.m());
      for (int i = 0; i < nlp.n(); ++i) {
        Eigen::VectorXd xp = x, xm = x;
        xp[i] += h;
        xm[i] -= h;
        nlp.constraints(xp.data(), true, gp.data());
        const double fp = nlp.objective(xp.data(), false);
        nlp.constraints(xm.data(), true, gm.data());
        const double fm = nlp.objective(xm.data(), false);
        J_fd.col(i) = (gp - gm) / (2 * h);
        grad_fd[i] = (fp - fm) / (2 * h);
      }
      for (size_t b = 0; b < nlp.blocks().size(); ++b) {
        const auto& block = nlp.blocks()[b];
        const int r0 = nlp.block_first_row(int(b));
        for (int r = r0; r < r0 + block->rows(); ++r) {
          const double scale = std::max(1.0, J_fd.row(r).norm());
          const double err = (J.row(r) - J_fd.row(r)).norm() / scale;
          // Signed distance is only piecewise smooth (the witness features change): a looser
          // bound there, tight everywhere else.
          const double tol = block->family() == "collision" ? 1e-4 : 1e-6;
          EXPECT_LE(err, tol) << program.name << " trial " << trial << " family " << block->family()
                              << " row " << r - r0 << "\nanalytic " << J.row(r) << "\nnumeric  "
                              << J_fd.row(r);
          for (int c = 0; c < nlp.n(); ++c) {
            if (std::abs(J_fd(r, c)) <= 1e-7 * scale) continue;
            EXPECT_TRUE(declared.count({r, c}))
                << program.name << " " << block->family() << " row " << r - r0 << " column " << c
                << " is nonzero but not declared";
          }
        }
      }
      const double gscale = std::max(1.0, grad_fd.norm());
      EXPECT_LE((grad - grad_fd).norm() / gscale, 1e-6)
          << program.name << " objective, trial " << trial;
    }
  }

  static Scene* scene_;
};
Scene* Derivatives::scene_ = nullptr;

TEST_F(Derivatives, RealiseStanceWithFreePlacements) {
  const Scene& s = *scene_;
  Program p{"realise", {}, false};
  p.request.contacts = {test::task(s, "robot/l_sole", "env/floor"),
                        test::task(s, "robot/r_sole", "env/floor")};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

TEST_F(Derivatives, Case1AddedContactWithTargetAndFixedPlacements) {
  const Scene& s = *scene_;
  Program p{"case1", {}, false};
  ContactTask left = test::task(s, "robot/l_sole", "env/floor");
  left.placement = Placement{0.01, 0.1, 0.05};
  ContactTask right = test::task(s, "robot/r_sole", "env/floor");
  right.placement = Placement{-0.02, -0.1, -0.1};
  ContactTask hand = test::task(s, "robot/r_palm", "env/wall", false);
  hand.placement_target = Placement{0.3, 0.2, 0.0};
  p.request.contacts = {left, right, hand};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

TEST_F(Derivatives, Case2RemovedContactAndBilateral) {
  const Scene& s = *scene_;
  Program p{"case2", {}, false};
  ContactTask left = test::task(s, "robot/l_sole", "env/floor");
  left.placement = Placement{0.0, 0.1, 0.0};
  ContactTask right = test::task(s, "robot/r_sole", "env/floor", false);
  right.placement = Placement{0.0, -0.1, 0.0};
  ContactTask hand = test::task(s, "robot/l_palm", "env/wall");
  hand.contact.bilateral = true;
  p.request.contacts = {left, right, hand};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

TEST_F(Derivatives, CollisionRowsIncludingPenetratingPairs) {
  const Scene& s = *scene_;
  Program p{"collision", {}, true};
  p.request.contacts = {test::task(s, "robot/l_sole", "env/floor")};
  // Crouched and leaning so that some links penetrate each other and the floor.
  Eigen::VectorXd q = test::standing_configuration(s);
  q[2] = 0.6;
  const Model& m = *s.system.entity(0).model;
  q[7 + m.find_dof("l_hip_p")] = -1.9;
  q[7 + m.find_dof("l_knee_p")] = 2.3;
  q[7 + m.find_dof("r_shoulder_r")] = -0.4;
  p.request.q_init = q;
  check(p);
}

// Point contacts (round fingertips, geometry only): E9 with the centre one radius above s2's plane,
// free (case 1, with an E25 target) and at a fixed placement (E10-E11).
TEST_F(Derivatives, PointContactsFreeAndFixed) {
  const Scene s = test::humanoid_scene_with_tips("wall");
  Program p{"point", {}, false, &s};
  ContactTask tip = test::task(s, "robot/l_tip", "env/wall", false);
  tip.placement_target = Placement{0.1, -0.2, 0.0};
  ContactTask fixed_tip = test::task(s, "robot/r_tip", "env/floor", false);
  fixed_tip.placement = Placement{0.3, -0.4, 0.7};
  p.request.contacts = {test::task(s, "robot/l_sole", "env/floor"), tip, fixed_tip};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

// Loaded point contacts: their force enters E16 and, at c - r z2, E17 and E18 (the couple
// -r z2 x f turning with s2, on l1's joints and, for the thigh, on l2's).
TEST_F(Derivatives, LoadedPointContactInEquilibrium) {
  const Scene s = test::humanoid_scene_with_tips("wall");
  Program p{"loaded point", {}, false, &s};
  ContactTask fixed_tip = test::task(s, "robot/l_tip", "env/wall");
  fixed_tip.placement = Placement{0.1, 0.2, 0.0};
  // The right tip on the robot's own left thigh: s2 moves, so the offset -r z2 turns with it.
  p.request.contacts = {test::task(s, "robot/l_sole", "env/floor"),
                        test::task(s, "robot/r_tip", "robot/l_thigh"), fixed_tip};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

// A bilateral point contact (free force in R^3, its couple -r z2 x f still turning with s2): the
// right tip gripping the robot's own left thigh.
TEST_F(Derivatives, BilateralPointContact) {
  const Scene s = test::humanoid_scene_with_tips("wall");
  Program p{"bilateral point", {}, false, &s};
  ContactTask grip = test::task(s, "robot/r_tip", "robot/l_thigh");
  grip.contact.bilateral = true;
  p.request.contacts = {test::task(s, "robot/l_sole", "env/floor"),
                        test::task(s, "robot/r_sole", "env/floor"), grip};
  p.request.q_init = test::standing_configuration(s);
  check(p);
}

// Point fingertips holding the ball of hand_ball_rotate.yaml: the ball is an object, so E16-E17
// hold for it and the offset -r z2 of each load point turns with the ball (s2).
TEST_F(Derivatives, LoadedPointContactsOnAnObject) {
  Scenario scenario = load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml"));
  Program p{"point tips on the ball", {}, false, &scenario.scene};
  p.request = test::with_point_tips(scenario);
  ASSERT_EQ(p.request.contacts.size(), 4u);  // four fingertips
  check(p);
}

}  // namespace
}  // namespace stanceplan
