// `surfaces: auto` on the project's own environments: every hand-written support surface of their
// surface files is extracted, the same polygon within 1 cm (Hausdorff distance between the
// boundaries); the mesh-only staircase (scripts/assets/mesh_stairs.py) gives its treads; the
// scenario field and its faults.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/inspect_command.h"
#include "planner/contact/affordances.h"
#include "planner/contact/surface_file.h"
#include "planner/io/scenario.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;

double distance_to_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

double distance_to_boundary(const Vector3d& p, const std::vector<Vector3d>& polygon) {
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i)
    d = std::min(d, distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return d;
}

// The largest distance from a point of one boundary to the other, with the boundaries sampled
// every millimetre (and at every vertex): the Hausdorff distance within 1 mm.
double one_way(const std::vector<Vector3d>& from, const std::vector<Vector3d>& to) {
  double worst = 0.0;
  for (size_t i = 0; i < from.size(); ++i) {
    const Vector3d& a = from[i];
    const Vector3d& b = from[(i + 1) % from.size()];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 1e-3)));
    for (int k = 0; k < n; ++k)
      worst = std::max(worst, distance_to_boundary(a + (b - a) * (double(k) / n), to));
  }
  return worst;
}

double hausdorff(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  return std::max(one_way(a, b), one_way(b, a));
}

// The extracted surface on `link` with the normal of `hand` closest to it, and the distance.
const Affordance* closest(const std::vector<Affordance>& found, const Surface& hand,
                          double* distance) {
  const Affordance* best = nullptr;
  *distance = std::numeric_limits<double>::infinity();
  for (const Affordance& a : found) {
    if (a.surface.link != hand.link || a.surface.normal_L().dot(hand.normal_L()) < 0.9999) continue;
    const double d = hausdorff(a.surface.vertices_L(), hand.vertices_L());
    if (d < *distance) *distance = d, best = &a;
  }
  return best;
}

TEST(ExtractedEnvironments, EveryHandWrittenSupportIsExtractedWithin1cm) {
  int supports = 0, leans = 0;
  for (const auto& entry : fs::directory_iterator(test::source_path("assets/environments"))) {
    const std::string name = entry.path().filename().string();
    const fs::path surface_file = entry.path() / (name + ".surfaces.yaml");
    if (!fs::exists(surface_file)) continue;
    const Model model = load_urdf((entry.path() / (name + ".urdf")).string());
    // Link frames parallel to the root's: a link-frame normal is the world's.
    for (const Joint& joint : model.joints)
      ASSERT_TRUE(joint.T_PJ.linear().isIdentity(1e-12)) << name << ": " << joint.name;
    const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
    for (const Surface& hand : load_surface_file(surface_file.string(), model)) {
      const bool support = hand.normal_L().z() >= std::cos(30.0 * M_PI / 180.0);
      double distance = 0.0;
      const Affordance* match = closest(found, hand, &distance);
      ASSERT_NE(match, nullptr) << name << "/" << hand.name << ": nothing with its normal";
      EXPECT_LE(distance, 0.01) << name << "/" << hand.name << " vs " << match->surface.name;
      EXPECT_EQ(match->kind, support ? AffordanceClass::Support : AffordanceClass::Lean)
          << name << "/" << hand.name;
      ++(support ? supports : leans);
    }
  }
  // flat_ground, desk_room, stairs, two_platforms, climb_gap, wall: 6 floors, the desk, the seat,
  // 5 treads, 4 platforms; the chair's back and the wall lean.
  EXPECT_EQ(supports, 17);
  EXPECT_EQ(leans, 2);
}

TEST(ExtractedEnvironments, TheMeshStaircaseGivesItsTreadsAndPlatform) {
  const Model model =
      load_urdf(test::source_path("assets/environments/mesh_stairs/mesh_stairs.urdf"));
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  std::vector<const Affordance*> supports;
  for (const Affordance& a : found)
    if (a.kind == AffordanceClass::Support) supports.push_back(&a);
  ASSERT_EQ(supports.size(), 6u);
  EXPECT_EQ(supports[0]->surface.link_name, "floor");
  EXPECT_NEAR(supports[0]->surface.area(), 48.0, 1e-9);
  // Tread k (1..4) from x = 0.35 + 0.3 (k - 1), 0.3 m deep; the platform from 1.55 to 2.35 m.
  for (int k = 1; k <= 5; ++k) {
    const Surface& s = supports[k]->surface;
    EXPECT_EQ(s.name, "support_" + std::to_string(k));
    EXPECT_EQ(s.link_name, "stairs");
    const double near = 0.35 + 0.3 * (k - 1), far = k == 5 ? 2.35 : near + 0.3, z = 0.1 * k;
    const std::vector<Vector3d> expected = {
        {near, -0.5, z}, {far, -0.5, z}, {far, 0.5, z}, {near, 0.5, z}};
    EXPECT_EQ(s.vertices_S.size(), 4u) << s.name;  // 60 or 160 triangles, one rectangle
    EXPECT_LE(hausdorff(s.vertices_L(), expected), 1e-6) << s.name;
  }
  // Each side of the flight (one non-convex staircase outline) is cut into convex pieces, one per
  // step: 5 per side; four risers, the back, four floor edges.
  int leans = 0;
  for (const Affordance& a : found) leans += a.kind == AffordanceClass::Lean;
  EXPECT_EQ(leans, 2 * 5 + 5 + 1 + 4);
}

// A scenario with the humanoid on flat ground whose `surfaces` field is `surfaces` (line 13).
std::string flat_ground_scenario(const std::string& name, const std::string& robot_surfaces,
                                 const std::string& surfaces) {
  const std::string assets = test::source_path("assets");
  const fs::path path = test::temp_dir("extracted") / (name + ".yaml");
  std::ofstream(path) << "format: stanceplan/scenario@1\n"
                      << "entities:\n"
                      << "  - name: robot\n"
                      << "    kind: floating\n"
                      << "    urdf: " << assets << "/robots/humanoid/humanoid.urdf\n"
                      << "    surfaces: " << robot_surfaces << "\n"
                      << "    configuration:\n"
                      << "      base_position: [0, 0, 0.9]\n"
                      << "  - name: env\n"
                      << "    kind: environment\n"
                      << "    urdf: " << assets << "/environments/flat_ground/flat_ground.urdf\n"
                      << "    base_pose: {position: [0, 0, 0]}\n"
                      << "    surfaces: " << surfaces << "\n"
                      << "stances:\n"
                      << "  initial:\n"
                      << "    - {s1: robot/l_sole, s2: env/support_0}\n"
                      << "    - {s1: robot/r_sole, s2: env/support_0}\n"
                      << "  goal:\n"
                      << "    - {s1: robot/l_sole, s2: env/support_0}\n"
                      << "    - {s1: robot/r_sole, s2: env/support_0}\n";
  return path.string();
}

std::string humanoid_surfaces() {
  return test::source_path("assets/robots/humanoid/humanoid.surfaces.yaml");
}

std::string error_of(const std::string& path) {
  try {
    load_scenario(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ExtractedEnvironments, TheScenarioFieldTakesAutoAndItsOptions) {
  const Scenario plain = load_scenario(flat_ground_scenario("auto", humanoid_surfaces(), "auto"));
  const int env = plain.scene.system.find_entity("env");
  // The floor's top and its four edges (8 x 0.05 and 6 x 0.05 m).
  ASSERT_EQ(plain.scene.surfaces.of(env).size(), 5u);
  EXPECT_EQ(plain.scene.surfaces.of(env)[0].name, "support_0");
  EXPECT_NEAR(plain.scene.surfaces.of(env)[0].area(), 48.0, 1e-9);
  const Scenario options = load_scenario(
      flat_ground_scenario("options", humanoid_surfaces(), "{auto: {min_area: 0.5, inset: 0.5}}"));
  ASSERT_EQ(options.scene.surfaces.of(env).size(), 1u);
  EXPECT_NEAR(options.scene.surfaces.of(env)[0].area(), 7.0 * 5.0, 1e-9);
}

TEST(ExtractedEnvironments, TheScenarioFieldsFaultsNameTheField) {
  std::string path = flat_ground_scenario("robot", "auto", "auto");
  EXPECT_EQ(error_of(path), path +
                                ":6: entities[0].surfaces: auto surfaces are for environments only "
                                "(entity \"robot\" is floating): give a surface file");
  path = flat_ground_scenario("slope", humanoid_surfaces(), "{auto: {slope: 95}}");
  EXPECT_EQ(error_of(path), path +
                                ":13: entities[1].surfaces.auto.slope: expected a number from 0 "
                                "to 90 (degrees), found 95");
  path = flat_ground_scenario("unknown", humanoid_surfaces(), "{auto: {slop: 30}}");
  EXPECT_EQ(error_of(path),
            path +
                ":13: entities[1].surfaces.auto.slop: unknown field (expected one of: slope, "
                "lean, angle_tolerance, offset_tolerance, min_area, inset)");
  path = flat_ground_scenario("inset", humanoid_surfaces(), "{auto: {inset: -0.01}}");
  EXPECT_EQ(error_of(path), path +
                                ":13: entities[1].surfaces.auto.inset: expected a number from 0 "
                                "to infinity (m), found -0.01");
}

TEST(ExtractedEnvironments, InspectListsThemWithTheirClass) {
  app::InspectOptions options;
  options.urdf = test::source_path("assets/environments/flat_ground/flat_ground.urdf");
  options.surfaces = "auto";
  options.kind = "environment";
  std::ostringstream text, err;
  ASSERT_EQ(app::run_inspect(options, text, err), 0);
  EXPECT_THAT(text.str(), ::testing::HasSubstr("4 vertices, 48.0000 m^2, support\n"));
  EXPECT_THAT(text.str(), ::testing::HasSubstr(
                              "  support_0: normal [0.0000, 0.0000, 1.0000], vertices (link frame, "
                              "m) [-2.5000, -3.0000, 0.0000] [5.5000, -3.0000, 0.0000] [5.5000, "
                              "3.0000, 0.0000] [-2.5000, 3.0000, 0.0000]\n"));
  options.json = true;
  std::ostringstream json_out;
  ASSERT_EQ(app::run_inspect(options, json_out, err), 0);
  const nlohmann::json d = nlohmann::json::parse(json_out.str());
  ASSERT_EQ(d["surfaces"].size(), 5u);
  EXPECT_EQ(d["surfaces"][0]["name"], "support_0");
  EXPECT_EQ(d["surfaces"][0]["class"], "support");
  EXPECT_EQ(d["surfaces"][1]["name"], "lean_0");
  EXPECT_EQ(d["surfaces"][1]["class"], "lean");
}

}  // namespace
}  // namespace stanceplan
