// The URDF loader on the real robots of ../shared/robots and on every class of bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/input_errors.h"
#include "tests/support/paths.h"
#include "tests/support/test_models.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

UrdfOptions with_package(const std::string& dir) {
  UrdfOptions options;
  options.packages.directories = {dir};
  options.packages.use_ros_package_path = false;
  return options;
}

using test::error_of;

TEST(UrdfLoader, TalosHas32ActuatedJointsAndItsDocumentedMass) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const Model talos = load_urdf(test::talos_urdf(), with_package(test::talos_package_dir()));
  EXPECT_EQ(talos.name, "talos");
  EXPECT_EQ(talos.num_dofs(), 32);
  EXPECT_NEAR(talos.total_mass, 90.2722, 1e-3);
  EXPECT_TRUE(talos.load_warnings.empty()) << talos.load_warnings.front();
  EXPECT_TRUE(talos.ignored_inertias.empty()) << talos.ignored_inertias.front().link;
  int meshes = 0, mirrored = 0;
  for (const Link& link : talos.links)
    for (const auto* list : {&link.collisions, &link.visuals})
      for (const LinkGeometry& g : *list) {
        if (g.shape.type != ShapeType::Mesh) continue;
        ++meshes;
        EXPECT_TRUE(std::filesystem::is_regular_file(g.shape.mesh_path)) << g.shape.mesh_uri;
        if (g.shape.mesh_scale.prod() < 0) ++mirrored;
      }
  EXPECT_GT(meshes, 40);
  EXPECT_GT(mirrored, 0);
  // Mimic on a fixed joint (gripper fingers) is ignored: those joints stay fixed.
  const Joint& finger = talos.joints[talos.find_joint("gripper_left_fingertip_1_joint")];
  EXPECT_FALSE(finger.movable());
  const Joint& knee = talos.joints[talos.find_joint("leg_left_4_joint")];
  EXPECT_NEAR(knee.lower, 0.0, 1e-12);
  EXPECT_NEAR(knee.upper, 2.618, 1e-12);
  EXPECT_NEAR(knee.effort, 300.0, 1e-12);
}

TEST(UrdfLoader, PandaHasPrismaticAndMimicFingers) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const Model panda = load_urdf(test::panda_urdf(), with_package(test::panda_package_dir()));
  EXPECT_EQ(panda.num_dofs(), 8);  // 7 revolute + 1 independent finger
  EXPECT_NEAR(panda.total_mass, 17.4519, 1e-3);
  const Joint& f1 = panda.joints[panda.find_joint("panda_finger_joint1")];
  const Joint& f2 = panda.joints[panda.find_joint("panda_finger_joint2")];
  EXPECT_EQ(f1.type, JointType::Prismatic);
  EXPECT_TRUE(f2.is_mimic);
  EXPECT_EQ(f2.dof, f1.dof);
  bool dae = false, stl = false;
  for (const Link& link : panda.links) {
    for (const LinkGeometry& g : link.visuals) dae |= g.shape.mesh_path.ends_with(".dae");
    for (const LinkGeometry& g : link.collisions) stl |= g.shape.mesh_path.ends_with(".stl");
  }
  EXPECT_TRUE(dae);
  EXPECT_TRUE(stl);
}

TEST(UrdfLoader, LinksAreInTopologicalOrder) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const Model talos = load_urdf(test::talos_urdf(), with_package(test::talos_package_dir()));
  EXPECT_EQ(talos.links[0].name, "base_link");
  for (int i = 1; i < talos.num_links(); ++i) EXPECT_LT(talos.links[i].parent_link, i);
}

class BadUrdf : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const auto dir = test::temp_dir("stanceplan_bad_urdf");
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
  }
};

TEST_F(BadUrdf, MissingFileIsNamed) {
  EXPECT_EQ(error_of([] { load_urdf("/nonexistent/robot.urdf"); }),
            "/nonexistent/robot.urdf: no such file");
}

TEST_F(BadUrdf, MalformedXmlIsReported) {
  const std::string path = write("malformed.urdf", "<robot name=\"r\"><link name=\"a\"></robot");
  const std::string message = error_of([&] { load_urdf(path); });
  EXPECT_THAT(message, HasSubstr(path + ": not a valid URDF"));
}

TEST_F(BadUrdf, TwoRootsAreNamed) {
  const std::string path =
      write("two_roots.urdf", "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/></robot>");
  const std::string message = error_of([&] { load_urdf(path); });
  EXPECT_THAT(message, HasSubstr(path + ": not a valid URDF"));
  EXPECT_THAT(message, HasSubstr("root"));
}

TEST_F(BadUrdf, UnresolvablePackageUriNamesUriAndDirectoriesTried) {
  const std::string path = write("package.urdf", R"(<robot name="r"><link name="a">
    <collision><geometry><mesh filename="package://nowhere/meshes/a.stl"/></geometry></collision>
    </link></robot>)");
  const std::string message = error_of([&] { load_urdf(path, with_package("/tmp/pkgdir")); });
  EXPECT_THAT(message, HasSubstr("link \"a\": collision mesh \"package://nowhere/meshes/a.stl\" "
                                 "cannot be resolved; tried: /tmp/pkgdir/nowhere/meshes/a.stl, "
                                 "/tmp/pkgdir/meshes/a.stl"));
}

TEST_F(BadUrdf, MissingMeshFileIsNamed) {
  const std::string path = write("mesh.urdf", R"(<robot name="r"><link name="a">
    <collision><geometry><mesh filename="meshes/missing.stl"/></geometry></collision>
    </link></robot>)");
  const std::string message = error_of([&] { load_urdf(path); });
  EXPECT_THAT(message, HasSubstr("collision mesh \"meshes/missing.stl\" cannot be resolved"));
  EXPECT_THAT(message, HasSubstr("stanceplan_bad_urdf/meshes/missing.stl"));
}

TEST_F(BadUrdf, MissingVisualMeshIsAWarningNotAnError) {
  const std::string path = write("visual.urdf", R"(<robot name="r"><link name="a">
    <visual><geometry><mesh filename="meshes/missing.dae"/></geometry></visual>
    <visual><geometry><box size="1 1 1"/></geometry></visual>
    </link></robot>)");
  const Model model = load_urdf(path);
  ASSERT_EQ(model.load_warnings.size(), 1u);
  EXPECT_THAT(model.load_warnings[0], HasSubstr("visual mesh \"meshes/missing.dae\""));
  EXPECT_EQ(model.links[0].visuals.size(), 1u);  // the box remains
}

TEST_F(BadUrdf, UnknownMimicSourceIsNamed) {
  const std::string path = write("mimic.urdf", R"(<robot name="r"><link name="a"/><link name="b"/>
    <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="ghost"/></joint></robot>)");
  EXPECT_EQ(error_of([&] { load_urdf(path); }),
            path + ": joint \"j\": mimics \"ghost\", which does not exist");
}

TEST_F(BadUrdf, FloatingJointInsideTheTreeIsRejected) {
  const std::string path =
      write("floating.urdf", R"(<robot name="r"><link name="a"/><link name="b"/>
    <joint name="free" type="floating"><parent link="a"/><child link="b"/></joint></robot>)");
  EXPECT_THAT(error_of([&] { load_urdf(path); }),
              HasSubstr(path + ": joint \"free\": type floating is not supported"));
}

// A published model's inertia tensors may be ones no rigid body has (CAD exports); the statics
// use the mass and centre of mass only, so the model loads, the tensors are set to zero and listed.
TEST(UrdfLoaderInertia, TensorsNoBodyHasAreIgnoredWithTheLinkAndTheFault) {
  const std::string path = test::source_path("tests/data/inertia_faults/cad_arm.urdf");
  const Model model = load_urdf(path);
  EXPECT_NEAR(model.total_mass, 4.25, 1e-12);  // every mass counts
  ASSERT_EQ(model.ignored_inertias.size(), 2u);
  EXPECT_EQ(model.ignored_inertias[0].link, "upper");
  EXPECT_EQ(model.ignored_inertias[0].fault,
            "triangle inequality broken: principal moments 0.125 0.125 0.5, 0.5 > 0.25");
  EXPECT_EQ(model.ignored_inertias[1].link, "forearm");
  EXPECT_EQ(model.ignored_inertias[1].fault,
            "not positive semi-definite: principal moments -0.03125 0.0625 0.0625");
  const Link& upper = model.links[model.find_link("upper")];
  EXPECT_TRUE(upper.inertial.I_C.isZero(0.0));
  EXPECT_EQ(upper.inertial.p_LC, Eigen::Vector3d(0, 0, 0.15));
  EXPECT_FALSE(model.links[model.find_link("base")].inertial.I_C.isZero(0.0));
  EXPECT_TRUE(model.load_warnings.empty());
  EXPECT_EQ(ignored_inertias_warning(model.source_file, model.ignored_inertias),
            path +
                ": inertia of 2 links ignored (not used by the statics): upper (triangle "
                "inequality broken: principal moments 0.125 0.125 0.5, 0.5 > 0.25), forearm (not "
                "positive semi-definite: principal moments -0.03125 0.0625 0.0625)");
}

TEST_F(BadUrdf, NegativeMassIsRefusedWithFileLinkAndValue) {
  const std::string path = write("negative_mass.urdf", R"(<robot name="r"><link name="body">
    <inertial><mass value="-0.5"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/>
    </inertial></link></robot>)");
  EXPECT_EQ(error_of([&] { load_urdf(path); }),
            path + ": link \"body\": <inertial> mass: expected a number >= 0 (kg), found -0.5");
}

TEST(UrdfLoaderString, BranchingModelHasExpectedStructure) {
  const Model m = load_urdf_string(test::kBranchingUrdf, ".");
  EXPECT_EQ(m.num_links(), 8);
  EXPECT_EQ(m.num_dofs(), 5);
  EXPECT_NEAR(m.total_mass, 6.8, 1e-12);
  EXPECT_EQ(m.joints[m.find_joint("j3")].type, JointType::Continuous);
  EXPECT_FALSE(m.joints[m.find_joint("j3")].has_position_limits);
  EXPECT_TRUE(m.adjacent(m.find_link("a1"), m.find_link("base")));
  EXPECT_FALSE(m.adjacent(m.find_link("a2"), m.find_link("base")));
}

}  // namespace
}  // namespace stanceplan
