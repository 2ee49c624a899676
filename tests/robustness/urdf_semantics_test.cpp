// Physically meaningless URDF values that the statics would use (a negative mass, a zero axis,
// lower > upper, negative effort or velocity limits, non-positive shape sizes, NaN or inf) are
// rejected by load_urdf with the file, the link or joint, what was expected and what was found.
// Some of these urdfdom 3.0 rejects itself; some it accepts silently (negative mass, zero axis,
// lower > upper) and some it half reads with an error logged (a NaN mass, a NaN box size: the
// collision body is dropped) — all must fail here. An inertia tensor no rigid body has (not
// positive semi-definite, the triangle inequality broken, non-zero on a massless link) is not
// used by the statics: the model loads and lists the link and the fault. The project's own models
// and the shared robots still load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;

// A two-link robot: link "a" holds `link_body`, joint "j" (revolute, a -> b) holds `joint_body`.
std::string robot(const std::string& link_body, const std::string& joint_body) {
  return "<robot name=\"r\"><link name=\"a\">" + link_body +
         "</link><link name=\"b\"/><joint name=\"j\" type=\"revolute\"><parent link=\"a\"/>"
         "<child link=\"b\"/>" +
         joint_body + "</joint></robot>";
}

const char* kAxis = "<axis xyz=\"0 0 1\"/>";
const char* kLimit = "<limit lower=\"-1\" upper=\"1\" effort=\"10\" velocity=\"2\"/>";
const std::string kJoint = std::string(kAxis) + kLimit;

std::string inertial(const std::string& mass, const std::string& inertia) {
  return "<inertial><mass value=\"" + mass + "\"/><inertia " + inertia + "/></inertial>";
}
const char* kUnitInertia = "ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"";

class UrdfSemantics : public ::testing::Test {
 protected:
  // Writes `xml` to a file of its own and returns load_urdf's error ("" when it loads).
  std::string error_of(const std::string& xml) {
    path_ =
        (test::temp_dir("urdf_semantics") /
         (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".urdf"))
            .string();
    std::ofstream(path_) << xml;
    try {
      ignored_ = load_urdf(path_).ignored_inertias;
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  // The ignored tensors of the last model error_of loaded, as "link: fault; ...".
  std::string ignored() const {
    std::string out;
    for (const IgnoredInertia& i : ignored_) {
      if (!out.empty()) out += "; ";
      out += i.link + ": " + i.fault;
    }
    return out;
  }
  std::string path_;
  std::vector<IgnoredInertia> ignored_;
};

TEST_F(UrdfSemantics, AWellFormedRobotLoads) {
  EXPECT_EQ(error_of(robot(inertial("1", kUnitInertia), std::string(kAxis) + kLimit)), "");
  EXPECT_EQ(ignored(), "");
}

TEST_F(UrdfSemantics, NegativeMass) {
  const std::string e = error_of(robot(inertial("-2.5", kUnitInertia), kJoint));
  EXPECT_EQ(e, path_ + ": link \"a\": <inertial> mass: expected a number >= 0 (kg), found -2.5");
}

// A negative mass is refused even with a tensor no body has: the mass is checked first.
TEST_F(UrdfSemantics, NegativeMassWithABadTensor) {
  const std::string e = error_of(robot(
      inertial("-1", "ixx=\"-1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\""), kJoint));
  EXPECT_EQ(e, path_ + ": link \"a\": <inertial> mass: expected a number >= 0 (kg), found -1");
}

TEST_F(UrdfSemantics, NanCentreOfMass) {
  const std::string e =
      error_of(robot("<inertial><origin xyz=\"0 0 nan\"/><mass value=\"1\"/><inertia " +
                         std::string(kUnitInertia) + "/></inertial>",
                     kJoint));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Unable to parse component [nan] to a double (while "
                   "parsing a vector value); Could not parse inertial element for Link [a]");
}

// No mass, so no gravity: the tensor is meaningless but harmless.
TEST_F(UrdfSemantics, ZeroMassWithAnInertiaLoadsAndIgnoresIt) {
  EXPECT_EQ(error_of(robot(inertial("0", kUnitInertia), kJoint)), "");
  EXPECT_EQ(ignored(), "a: a non-zero tensor on a link of mass 0");
}

// Sensor and tool frames of real robots (TALOS, the Panda) carry mass 0 and a zero inertia.
TEST_F(UrdfSemantics, MasslessFrameLoads) {
  EXPECT_EQ(
      error_of(robot(inertial("0", "ixx=\"0\" iyy=\"0\" izz=\"0\" ixy=\"0\" ixz=\"0\" iyz=\"0\""),
                     kJoint)),
      "");
}

TEST_F(UrdfSemantics, InertiaNotPositiveSemiDefiniteLoadsAndIsIgnored) {
  EXPECT_EQ(
      error_of(robot(inertial("1", "ixx=\"-1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\""),
                     kJoint)),
      "");
  EXPECT_EQ(ignored(), "a: not positive semi-definite: principal moments -1 1 1");
}

TEST_F(UrdfSemantics, InertiaBreakingTheTriangleInequalityLoadsAndIsIgnored) {
  EXPECT_EQ(
      error_of(robot(inertial("1", "ixx=\"1\" iyy=\"1\" izz=\"3\" ixy=\"0\" ixz=\"0\" iyz=\"0\""),
                     kJoint)),
      "");
  EXPECT_EQ(ignored(), "a: triangle inequality broken: principal moments 1 1 3, 3 > 2");
}

// Rounded CAD tensors may exceed it slightly (TALOS: 1.3 % of the trace); 2 % is tolerated.
TEST_F(UrdfSemantics, InertiaWithinTwoPercentOfTheTriangleBoundaryLoads) {
  EXPECT_EQ(
      error_of(robot(
          inertial("1", "ixx=\"1\" iyy=\"1\" izz=\"2.05\" ixy=\"0\" ixz=\"0\" iyz=\"0\""), kJoint)),
      "");
  EXPECT_EQ(ignored(), "");
}

TEST_F(UrdfSemantics, InertiaOnTheTriangleBoundaryLoads) {
  // A thin rod: two equal moments, the third zero (a + b = c holds with equality).
  EXPECT_EQ(error_of(robot(
                inertial("1", "ixx=\"0.5\" iyy=\"0.5\" izz=\"0\" ixy=\"0\" ixz=\"0\" iyz=\"0\""),
                kJoint)),
            "");
}

// urdfdom logs "mass [nan] is not a float" and returns the model with a zeroed inertial.
TEST_F(UrdfSemantics, NanMassHalfReadByUrdfdom) {
  const std::string e = error_of(robot(inertial("nan", kUnitInertia), kJoint));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Inertial: mass [nan] is not a float; Could not parse "
                   "inertial element for Link [a]");
}

TEST_F(UrdfSemantics, InfiniteInertiaHalfReadByUrdfdom) {
  const std::string e = error_of(robot(
      inertial("1", "ixx=\"inf\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\""), kJoint));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Inertial: inertia element ixx is not a valid double; "
                   "Could not parse inertial element for Link [a]");
}

// urdfdom drops the collision element and returns the model: a robot without that body.
TEST_F(UrdfSemantics, NanBoxSizeDroppedByUrdfdom) {
  const std::string e = error_of(
      robot("<collision><geometry><box size=\"nan 1 1\"/></geometry></collision>", kJoint));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Unable to parse component [nan] to a double (while "
                   "parsing a vector value); Could not parse collision element for Link [a]");
}

TEST_F(UrdfSemantics, NanJointOrigin) {
  const std::string e =
      error_of(robot("", std::string("<origin xyz=\"0 nan 0\"/>") + kAxis + kLimit));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Unable to parse component [nan] to a double (while "
                   "parsing a vector value); Malformed parent origin element for joint [j]; joint "
                   "xml is not initialized correctly");
}

TEST_F(UrdfSemantics, InfiniteUpperLimit) {
  const std::string e = error_of(robot(
      "", std::string(kAxis) + "<limit lower=\"0\" upper=\"inf\" effort=\"1\" velocity=\"1\"/>"));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: upper value (inf) is not a valid float; Could not parse "
                   "limit element for joint [j]; joint xml is not initialized correctly");
}

TEST_F(UrdfSemantics, ZeroAxis) {
  const std::string e = error_of(robot("", std::string("<axis xyz=\"0 0 0\"/>") + kLimit));
  EXPECT_EQ(e, path_ + ": joint \"j\": <axis>: expected a non-zero finite vector, found 0 0 0");
}

TEST_F(UrdfSemantics, NanAxis) {
  const std::string e = error_of(robot("", std::string("<axis xyz=\"nan 0 1\"/>") + kLimit));
  EXPECT_EQ(e, path_ +
                   ": not a valid URDF: Malformed axis element for joint [j]: Unable to parse "
                   "component [nan] to a double (while parsing a vector value); joint xml is not "
                   "initialized correctly");
}

TEST_F(UrdfSemantics, LowerAboveUpper) {
  const std::string e =
      error_of(robot("", std::string(kAxis) +
                             "<limit lower=\"1.5\" upper=\"-0.5\" effort=\"1\" velocity=\"1\"/>"));
  EXPECT_EQ(e, path_ +
                   ": joint \"j\": <limit>: expected finite lower <= upper, found lower 1.5 and "
                   "upper -0.5");
}

TEST_F(UrdfSemantics, NegativeEffort) {
  const std::string e = error_of(robot(
      "", std::string(kAxis) + "<limit lower=\"-1\" upper=\"1\" effort=\"-3\" velocity=\"1\"/>"));
  EXPECT_EQ(e, path_ + ": joint \"j\": <limit> effort: expected a number >= 0, found -3");
}

TEST_F(UrdfSemantics, NegativeVelocity) {
  const std::string e =
      error_of(robot("", std::string(kAxis) +
                             "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"-0.25\"/>"));
  EXPECT_EQ(e, path_ + ": joint \"j\": <limit> velocity: expected a number >= 0, found -0.25");
}

TEST_F(UrdfSemantics, NegativeSphereRadius) {
  const std::string e = error_of(
      robot("<collision><geometry><sphere radius=\"-0.1\"/></geometry></collision>", kJoint));
  EXPECT_EQ(e, path_ +
                   ": link \"a\": collision <sphere> radius: expected positive numbers (m), found "
                   "-0.1");
}

TEST_F(UrdfSemantics, ZeroBoxSize) {
  const std::string e =
      error_of(robot("<visual><geometry><box size=\"1 0 2\"/></geometry></visual>", kJoint));
  EXPECT_EQ(e,
            path_ + ": link \"a\": visual <box> size: expected positive numbers (m), found 1 0 2");
}

TEST_F(UrdfSemantics, NegativeCylinderLength) {
  const std::string e = error_of(
      robot("<collision><geometry><cylinder radius=\"0.1\" length=\"-1\"/></geometry></collision>",
            kJoint));
  EXPECT_EQ(e, path_ +
                   ": link \"a\": collision <cylinder> radius and length: expected positive "
                   "numbers (m), found 0.1 -1");
}

// Every URDF of the project (assets/, tests/data/) and the shared robots load without warnings.
TEST(UrdfSemanticsOnRealModels, EveryProjectAndSharedModelLoads) {
  std::vector<std::string> paths;
  for (const char* root : {"assets", "tests/data"})
    for (const auto& entry : fs::recursive_directory_iterator(test::source_path(root)))
      if (entry.path().extension() == ".urdf" &&
          entry.path().string().find("fuzz_regressions") == std::string::npos)
        paths.push_back(entry.path().string());
  ASSERT_GE(paths.size(), 10u);
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    EXPECT_NO_THROW(load_urdf(path));
  }
  // The project's own models are checked above whether or not ../shared is there.
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  for (const auto& [urdf, package] :
       {std::pair{test::talos_urdf(), test::talos_package_dir()},
        std::pair{test::panda_urdf(), test::panda_package_dir()},
        std::pair{test::shared_path("robots/talos/robots/talos_data/robots/talos_reduced_box.urdf"),
                  test::talos_package_dir()},
        std::pair{
            test::shared_path("robots/panda/robots/panda_description/urdf/panda_collision.urdf"),
            test::panda_package_dir()}}) {
    SCOPED_TRACE(urdf);
    UrdfOptions options;
    options.packages.directories = {package};
    options.packages.use_ros_package_path = false;
    const Model model = load_urdf(urdf, options);
    EXPECT_TRUE(model.load_warnings.empty()) << model.load_warnings.front();
  }
}

}  // namespace
}  // namespace stanceplan
