// The trajectory CSV (planner/io/trajectory_csv.h, docs/PLAN_FORMAT.md): one row per configuration,
// steps and samples in order, at a steady time per step.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "planner/io/trajectory_csv.h"
#include "planner/motion/plan_motion.h"
#include "tests/support/forward_step.h"

namespace stanceplan {
namespace {

TEST(TrajectoryCsv, StepsAndSamplesInOrderAtASteadyTimePerStep) {
  test::ForwardStep fs = test::forward_step_plan();
  ASSERT_TRUE(add_motion(fs.scenario.scene, fs.scenario.solver, MotionOptions{}, fs.plan).solved());
  const std::string csv = trajectory_csv(fs.scenario.scene, fs.plan, 0, 2.0);
  std::istringstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("time_s,step,base_x,base_y,base_z,base_qw,base_qx,base_qy,base_qz,", 0),
            0u);
  const Model& model = *fs.scenario.scene.system.entity(0).model;
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 8 + model.num_dofs());
  size_t rows = 0;
  double last_time = -1.0;
  std::string line, last_row;
  while (std::getline(in, line)) {
    last_row = line;
    const double time = std::stod(line);
    EXPECT_GT(time, last_time) << line;
    last_time = time;
    ++rows;
  }
  const size_t samples =
      fs.plan.steps[1].motion->samples.size() + fs.plan.steps[2].motion->samples.size();
  EXPECT_EQ(rows, 3 + samples);
  EXPECT_DOUBLE_EQ(last_time, 4.0);                 // step 2 at 2 x 2 s
  EXPECT_EQ(last_row.rfind("4.000000,2,", 0), 0u);  // the last row is step 2
}

}  // namespace
}  // namespace stanceplan
