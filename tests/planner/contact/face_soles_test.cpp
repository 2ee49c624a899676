// Soles taken from the feet's collision geometry (`face: -z`) instead of measured vertices: on the
// project's humanoid (a box sole plate under an ankle block) they are its measured soles exactly
// and the walk of scenarios/humanoid_walk.yaml plans and certifies on them; on TALOS (a mesh per
// foot, ../shared/robots/talos) they match the measured soles of tests/data/talos/ within 5 mm and
// the walk of tests/data/talos/talos_walk.yaml plans and certifies on them.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "planner/contact/link_faces.h"
#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Replaces the one occurrence of `from` in *text, failing the test when there is none.
void replace_once(std::string* text, const std::string& from, const std::string& to) {
  const size_t at = text->find(from);
  ASSERT_NE(at, std::string::npos) << "\"" << from << "\" is not in the scenario any more";
  text->replace(at, from.size(), to);
}

void replace_all(std::string* text, const std::string& from, const std::string& to) {
  ASSERT_NE(text->find(from), std::string::npos) << "\"" << from << "\" is not in the scenario";
  for (size_t at = text->find(from); at != std::string::npos; at = text->find(from, at + to.size()))
    text->replace(at, from.size(), to);
}

// The humanoid's surface file with its soles given as `face: -z` of the foot links.
std::string humanoid_face_soles_file() {
  YAML::Node root =
      YAML::LoadFile(test::source_path("assets/robots/humanoid/humanoid.surfaces.yaml"));
  int replaced = 0;
  for (YAML::Node surface : root["surfaces"]) {
    const std::string name = surface["name"].as<std::string>();
    if (name != "l_sole" && name != "r_sole") continue;
    YAML::Node face;
    face["name"] = name;
    face["link"] = surface["link"];
    face["face"] = "-z";
    surface = face;
    ++replaced;
  }
  EXPECT_EQ(replaced, 2);
  const std::string path = (test::temp_dir("face_soles") / "humanoid.surfaces.yaml").string();
  YAML::Emitter out;
  out << root;
  std::ofstream(path) << out.c_str() << "\n";
  return path;
}

const Surface& named(const std::vector<Surface>& surfaces, const std::string& name) {
  for (const Surface& s : surfaces)
    if (s.name == name) return s;
  throw std::runtime_error("no surface " + name);
}

TEST(FaceSoles, HumanoidFaceSolesAreItsMeasuredSoles) {
  const Model model = load_urdf(test::source_path("assets/robots/humanoid/humanoid.urdf"));
  const std::vector<Surface> measured =
      load_surface_file(test::source_path("assets/robots/humanoid/humanoid.surfaces.yaml"), model);
  const std::vector<Surface> faces = load_surface_file(humanoid_face_soles_file(), model);
  ASSERT_EQ(faces.size(), measured.size());
  for (const char* sole : {"l_sole", "r_sole"}) {
    const Surface& m = named(measured, sole);
    const Surface& f = named(faces, sole);
    EXPECT_EQ(f.link, m.link);
    EXPECT_TRUE(f.T_LS.isApprox(m.T_LS, 1e-12)) << sole;
    // The same corners, listed from another one.
    ASSERT_EQ(f.vertices_S.size(), m.vertices_S.size()) << sole;
    for (const Eigen::Vector2d& v : m.vertices_S)
      EXPECT_TRUE(std::any_of(f.vertices_S.begin(), f.vertices_S.end(),
                              [&](const Eigen::Vector2d& w) { return (v - w).norm() < 1e-12; }))
          << sole << " has no corner " << v.transpose();
  }
}

TEST(FaceSoles, HumanoidWalksOnFaceSolesAndCertifies) {
  std::string text = read_text(test::source_path("scenarios/humanoid_walk.yaml"));
  replace_all(&text, "../assets/", test::source_path("assets") + "/");
  replace_once(&text,
               "surfaces: " + test::source_path("assets/robots/humanoid/humanoid.surfaces.yaml"),
               "surfaces: " + humanoid_face_soles_file());
  const std::string path = (test::temp_dir("face_soles") / "humanoid_walk.yaml").string();
  std::ofstream(path) << text;
  const Scenario scenario = load_scenario(path);
  SearchOptions options = scenario.search;
  options.threads = 1;
  const SearchResult result = StanceSearch(scenario, options).run();
  test::expect_certified(scenario, result, "humanoid_walk_face_soles");
  ASSERT_EQ(result.status, PlanStatus::Found);
  // 1.5 m forward: the last posture's base over the goal's feet.
  EXPECT_NEAR(result.plan.steps.back().q[0], 1.5, 0.05);
}

Model talos() {
  UrdfOptions options;
  options.packages.directories = {test::talos_package_dir()};
  options.packages.use_ros_package_path = false;
  return load_urdf(test::talos_urdf(), options);
}

// Bounding box (x, y) of a sole's polygon and its plane's height, in the link frame.
struct SoleExtent {
  double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9, z_min = 1e9, z_max = -1e9;
  explicit SoleExtent(const std::vector<Eigen::Vector3d>& vertices_L) {
    for (const Eigen::Vector3d& v : vertices_L) {
      x_min = std::min(x_min, v.x()), x_max = std::max(x_max, v.x());
      y_min = std::min(y_min, v.y()), y_max = std::max(y_max, v.y());
      z_min = std::min(z_min, v.z()), z_max = std::max(z_max, v.z());
    }
  }
};

TEST(FaceSoles, TalosFaceSolesMatchTheMeasuredSoles) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const Model model = talos();
  const std::vector<Surface> measured =
      load_surface_file(test::source_path("tests/data/talos/talos.surfaces.yaml"), model);
  const std::vector<Surface> faces = load_surface_file(
      test::source_path("tests/data/link_faces/talos_face_soles.surfaces.yaml"), model);
  for (const char* sole : {"l_sole", "r_sole"}) {
    const Surface& f = named(faces, sole);
    EXPECT_LT(std::acos(-f.normal_L().z()), 1.0 * M_PI / 180.0) << sole;  // within 1 degree of -z
    const SoleExtent face(f.vertices_L()), ref(named(measured, sole).vertices_L());
    EXPECT_NEAR(face.z_min, -0.1074, 5e-3) << sole;
    EXPECT_NEAR(face.z_max, -0.1074, 5e-3) << sole;
    EXPECT_NEAR(face.x_min, ref.x_min, 5e-3) << sole;
    EXPECT_NEAR(face.x_max, ref.x_max, 5e-3) << sole;
    EXPECT_NEAR(face.y_min, ref.y_min, 5e-3) << sole;
    EXPECT_NEAR(face.y_max, ref.y_max, 5e-3) << sole;
    // Without the inset: the footprint of the mesh's lowest vertices, x -0.108 .. 0.097, y -0.062
    // .. 0.062, on the plane of the lowest one, z = -0.1074.
    const std::string link = f.link_name;
    const LinkFace whole = nearest_link_face(model, model.find_link(link), {0, 0, -1}, "-z");
    const SoleExtent footprint(whole.face.vertices);
    EXPECT_NEAR(whole.face.offset, 0.1074, 1e-4) << sole;
    EXPECT_NEAR(footprint.x_min, -0.108, 5e-3) << sole;
    EXPECT_NEAR(footprint.x_max, 0.097, 5e-3) << sole;
    EXPECT_NEAR(footprint.y_min, -0.062, 5e-3) << sole;
    EXPECT_NEAR(footprint.y_max, 0.062, 5e-3) << sole;
  }
}

TEST(FaceSoles, TalosWalksOnFaceSolesAndCertifies) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  std::string text = read_text(test::source_path("tests/data/talos/talos_walk.yaml"));
  replace_all(&text, "../../../../shared/", test::shared_dir() + "/");
  replace_all(&text, "../../../assets/", test::source_path("assets") + "/");
  replace_once(
      &text, "surfaces: talos.surfaces.yaml",
      "surfaces: " + test::source_path("tests/data/link_faces/talos_face_soles.surfaces.yaml"));
  const std::string path = (test::temp_dir("face_soles") / "talos_walk.yaml").string();
  std::ofstream(path) << text;
  const Scenario scenario = load_scenario(path);
  SearchOptions options = scenario.search;
  options.threads = 1;
  const SearchResult result = StanceSearch(scenario, options).run();
  test::expect_certified(scenario, result, "talos_walk_face_soles");
  ASSERT_EQ(result.status, PlanStatus::Found);
  // Both feet move 1 m: each leaves the floor and comes back at least once after the start.
  EXPECT_GE(result.plan.steps.size(), 1u + 2 * 2);
  EXPECT_NEAR(result.plan.steps.back().q[0], 1.0, 0.05);
}

}  // namespace
}  // namespace stanceplan
