// The render thread of the 3-D view and the panel's exports, off-screen (OSMesa: no display).
#include "app/gui/view_renderer.h"
#include "app/pipeline.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "app/gui/panel_exports.h"
#include "app/live/plan_session.h"
#include "render/figures/sequence.h"
#include "render/figures/step_caption.h"
#include "render/image/png_io.h"
#include "tests/support/paths.h"

namespace stanceplan::gui {
namespace {

using namespace std::chrono_literals;

class ViewRendererTest : public ::testing::Test {
 protected:
  ViewRendererTest()
      : scenario_(load_scenario(test::source_path("scenarios/humanoid_walk.yaml"))),
        meshes_(std::make_shared<render::MeshLibrary>()) {}

  ViewRequest request(int width, int height) const {
    ViewRequest r;
    r.q = scenario_.initial_configuration;
    r.width = width;
    r.height = height;
    r.caption = "initial";
    return r;
  }

  Scenario scenario_;
  std::shared_ptr<render::MeshLibrary> meshes_;
};

TEST_F(ViewRendererTest, RendersTheNewestRequestAtItsSize) {
  ViewRenderer view(scenario_.scene, render::RenderStyle::preview(), meshes_);
  const std::uint64_t first = view.request(request(160, 120));
  const std::uint64_t second = view.request(request(200, 100));  // replaces the first if not begun
  EXPECT_GT(second, first);
  ASSERT_TRUE(view.wait_for(second, 60s));
  const std::optional<ViewFrame> frame = view.take();
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->request, second) << "only the newest finished frame is kept";
  EXPECT_EQ(frame->image.width, 200);
  EXPECT_EQ(frame->image.height, 100);
  EXPECT_FALSE(view.take().has_value()) << "a frame is taken once";
  EXPECT_GE(view.frames_rendered(), 1);
  EXPECT_GT(view.median_render_ms(), 0.0);
}

// The same pixels as the renderer called directly: the live view has the PNGs' look.
TEST_F(ViewRendererTest, ShowsWhatTheRendererDraws) {
  const render::Camera camera;
  ViewRequest r = request(160, 120);
  r.camera = camera;
  ViewRenderer view(scenario_.scene, render::RenderStyle::preview(), meshes_);
  ASSERT_TRUE(view.wait_for(view.request(r), 60s));
  const std::optional<ViewFrame> frame = view.take();
  ASSERT_TRUE(frame.has_value());
  render::Renderer direct(160, 120, render::RenderStyle::preview(), meshes_);
  EXPECT_TRUE(frame->image == direct.render(scenario_.scene, r.q, {}, {}, camera, "initial"));
}

TEST_F(ViewRendererTest, ABadRequestBecomesAMessageNotACrash) {
  ViewRenderer view(scenario_.scene, render::RenderStyle::preview(), meshes_);
  ViewRequest bad = request(64, 64);
  bad.q = Eigen::VectorXd::Zero(3);  // not the system's size
  ASSERT_TRUE(view.wait_for(view.request(bad), 60s));
  const std::vector<std::string> messages = view.take_messages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].rfind("error: ", 0), 0u) << messages[0];
  EXPECT_FALSE(view.take().has_value());
}

TEST_F(ViewRendererTest, ExportsTheViewAndTheStripOfThePlanFound) {
  SearchOptions options = scenario_.search;
  options.threads = 1;
  app::PlanSession session(scenario_, options);
  session.start();
  ASSERT_TRUE(session.wait_until_finished(120s));
  ASSERT_EQ(session.result()->status, PlanStatus::Found);
  const auto plan = std::make_shared<const Plan>(session.result()->plan);
  EXPECT_EQ(render::plan_title(app::plan_view(scenario_, *plan)), "humanoid_walk");

  const std::filesystem::path dir = test::temp_dir("panel_exports");
  ViewRenderer view(scenario_.scene, render::RenderStyle::preview(), meshes_);
  ViewRequest r = request(320, 200);
  r.q = plan->steps.back().q;
  view.post(export_view_job(scenario_.scene, r, meshes_, (dir / "view.png").string()));
  view.post(export_strip_job(scenario_, plan, meshes_, (dir / "strip.png").string()));
  ASSERT_TRUE(view.wait_for(view.request(request(32, 32)), 120s));  // after both jobs
  const std::vector<std::string> messages = view.take_messages();
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0], "saved " + (dir / "view.png").string());
  EXPECT_EQ(messages[1], "saved " + (dir / "strip.png").string());
  const render::Image exported = render::read_png((dir / "view.png").string());
  EXPECT_EQ(exported.width, 320);
  EXPECT_EQ(exported.height, 200);
  const render::Image strip = render::read_png((dir / "strip.png").string());
  const render::Image expected = render::render_strip(
      app::plan_view(scenario_, *plan), render::StripOptions{}, render::SequenceOptions{}, meshes_);
  EXPECT_EQ(strip.width, expected.width);
  EXPECT_EQ(strip.height, expected.height);
}

}  // namespace
}  // namespace stanceplan::gui
