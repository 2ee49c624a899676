#pragma once
// A three-step plan made without the search, for tests of motions and of their certification:
// the walk's humanoid (scenarios/humanoid_walk.yaml) on both feet, then the left foot unloaded,
// then the left foot put down 20 cm ahead. Three solves: cheap enough for unit tests.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "planner/io/scenario.h"
#include "planner/plan/plan_step.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"
#include "tests/support/scenes.h"

namespace stanceplan::test {

struct ForwardStep {
  Scenario scenario;
  Plan plan;
};

inline ForwardStep forward_step_plan(double step_length = 0.2) {
  ForwardStep out{load_scenario(source_path("scenarios/humanoid_walk.yaml")), {}};
  const Scene& scene = out.scenario.scene;
  const PostureSolver solver(scene, out.scenario.solver);
  ContactTask left = task(scene, "robot/l_sole", "env/floor");
  ContactTask right = task(scene, "robot/r_sole", "env/floor");
  left.placement = Placement{-1.49, 0.085, 0.0};
  right.placement = Placement{-1.49, -0.085, 0.0};
  const auto step = [&](std::vector<ContactTask> tasks, const Eigen::VectorXd& q, Stance stance,
                        const std::string& action, std::optional<Contact> changed) {
    PostureRequest request;
    request.contacts = std::move(tasks);
    request.q_init = q;
    const PostureResult result = solver.solve(request);
    EXPECT_EQ(result.status, PostureStatus::Solved) << action << ": " << result.message;
    out.plan.steps.push_back(make_plan_step(request, result, stance, action, changed));
  };
  step({left, right}, out.scenario.initial_configuration,
       Stance(std::vector<Contact>{left.contact, right.contact}), "initial", std::nullopt);
  ContactTask unloaded = left;
  unloaded.loaded = false;
  step({unloaded, right}, out.plan.steps.back().q, Stance(std::vector<Contact>{right.contact}),
       "remove", left.contact);
  unloaded.placement->x += step_length;
  step({right, unloaded}, out.plan.steps.back().q,
       Stance(std::vector<Contact>{right.contact, left.contact}), "add", left.contact);
  return out;
}

}  // namespace stanceplan::test
