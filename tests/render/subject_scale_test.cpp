// Overlay sizes follow the subject's size (render/figures/sequence.cpp): a hand 0.3 m across gets
// force arrows, rings and markers scaled down with it, so that they do not hide the hand and the
// ball.
#include <gtest/gtest.h>

#include "app/pipeline.h"
#include "planner/io/plan_reader.h"
#include "render/figures/sequence.h"
#include "tests/render/render_fixtures.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan::render {
namespace {

// Pixels of the force arrows' red (flat colours: no lighting), edges included.
double red_fraction(const Image& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n += p[0] > 150 && p[1] < 110 && p[2] < 120 && p[0] - p[1] > 90;
    }
  return double(n) / (image.width * image.height);
}

TEST(SubjectScale, ForceArrowsOnTheHandStaySmallerThanTheBall) {
  const std::string dir = test::fresh_dir("subject_scale");
  const std::string plan_path = dir + "/grasp.json";
  const auto posture =
      test::run_cli({"posture", test::source_path("scenarios/hand_ball_rotate.yaml"), "--stance",
                     "initial", "--out", plan_path});
  ASSERT_EQ(posture.code, 0) << posture.err;
  const LoadedPlan plan = read_plan(plan_path, {.build_collision = false});
  SequenceOptions options;
  options.width = 640;
  options.height = 480;
  options.style = test::plain_style();
  options.style.center_of_mass = false;
  const Image image = SequenceRenderer(app::plan_view(plan), options).render_step(0);
  // At the humanoid's sizes (the largest arrow 0.3 m long, 6 mm thick) the arrows cover a large
  // part of the picture of a 9 cm ball; scaled to the hand they are thin strokes.
  const double red = red_fraction(image);
  EXPECT_GT(red, 0.0005);       // the arrows are drawn
  EXPECT_LT(red, 0.02) << red;  // 0.8 % here; 10.7 % at the humanoid's sizes
}

}  // namespace
}  // namespace stanceplan::render
