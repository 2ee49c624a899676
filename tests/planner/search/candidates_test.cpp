// Candidate enumeration (Adj+ / Adj-) and its documented pruning options.
#include <gtest/gtest.h>

#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/search/candidates.h"
#include "tests/support/paths.h"
#include "tests/support/point_tips.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

// True when the list adds (add) or removes (!add) the contact of surface s1 on the floor (soles)
// or on the wall (palms).
bool offers(const std::vector<Candidate>& list, const Scene& scene, const std::string& s1,
            bool add) {
  const std::string s2 = s1.find("palm") != std::string::npos ? "env/wall" : "env/floor";
  for (const Candidate& c : list)
    if (c.add == add && scene.surfaces.id(scene.system, c.contact.s1) == s1 &&
        scene.surfaces.id(scene.system, c.contact.s2) == s2)
      return true;
  return false;
}

TEST(Candidates, PruningRulesAndOptions) {
  const Scene scene = test::humanoid_scene("wall");
  const auto data = system_kinematics(scene.system, test::standing_configuration(scene));
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  const Contact palm = test::task(scene, "robot/r_palm", "env/wall").contact;
  const Stance goal({left, right, palm});
  SearchOptions options;
  options.contact_reach = 2.0;  // everything within reach
  // Standing on the left foot: the last support is never removed; the right foot may be added.
  auto on_left = enumerate_candidates(scene, data, Stance({left}), goal, options);
  EXPECT_FALSE(offers(on_left, scene, "robot/l_sole", false));
  EXPECT_TRUE(offers(on_left, scene, "robot/r_sole", true));
  EXPECT_TRUE(offers(on_left, scene, "robot/r_palm", true));
  // last_contacts: the palm only once both feet (the other goal contacts) are down.
  options.last_contacts = {{"robot/*_palm", "env/wall"}};
  on_left = enumerate_candidates(scene, data, Stance({left}), goal, options);
  EXPECT_FALSE(offers(on_left, scene, "robot/r_palm", true));
  EXPECT_TRUE(offers(enumerate_candidates(scene, data, Stance({left, right}), goal, options), scene,
                     "robot/r_palm", true));
  // contact_pairs: only the listed pairs.
  options = SearchOptions{};
  options.contact_reach = 2.0;
  options.contact_pairs = {{"robot/*_sole", "env/floor"}};
  on_left = enumerate_candidates(scene, data, Stance({left}), goal, options);
  EXPECT_TRUE(offers(on_left, scene, "robot/r_sole", true));
  EXPECT_FALSE(offers(on_left, scene, "robot/r_palm", true));
  // contact_reach: the hanging palms are farther than 0.3 m from the wall (x = 0.6 m).
  options = SearchOptions{};
  options.contact_reach = 0.3;
  EXPECT_FALSE(offers(enumerate_candidates(scene, data, Stance({left}), goal, options), scene,
                      "robot/r_palm", true));
}

// Point surfaces (the humanoid's round fingertips l_tip, r_tip) are offered with polygons only,
// always as s1 whatever the polygon's area, never with each other; their reach is the centre's
// distance to the polygon less the radius.
TEST(Candidates, APointIsAlwaysS1AndNeverMeetsAPoint) {
  const Scene scene = test::humanoid_scene_with_tips("wall");
  const auto data = system_kinematics(scene.system, test::standing_configuration(scene));
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  SearchOptions options;
  options.contact_reach = 2.0;
  int tips = 0;
  for (const Candidate& c : enumerate_candidates(scene, data, Stance({left, right}), {}, options)) {
    const Surface& s1 = scene.surfaces.get(c.contact.s1);
    const Surface& s2 = scene.surfaces.get(c.contact.s2);
    EXPECT_FALSE(s2.is_point()) << s1.name << " - " << s2.name;
    tips += s1.is_point();
  }
  EXPECT_EQ(tips, 4);  // each tip with the floor and the wall (no self contacts by default)
  // The left tip's centre hangs 0.15 m below the hand, well above the floor: in reach of it only
  // when the reach covers that height less the radius.
  const SurfaceRef tip = test::surface(scene, "robot/l_tip");
  const SurfaceRef floor = test::surface(scene, "env/floor");
  const double height =
      (data[0].T_WL[scene.surfaces.get(tip).link] * scene.surfaces.get(tip).center_L()).z();
  EXPECT_NEAR(surface_gap(scene, data, tip, floor), height - 0.02, 1e-9);
  EXPECT_NEAR(surface_gap(scene, data, floor, tip), height - 0.02, 1e-9);
}

TEST(Candidates, MinContactsKeepsThatManyContactsOnAFloatingBody) {
  const Scene scene = test::humanoid_scene("wall");
  const auto data = system_kinematics(scene.system, test::standing_configuration(scene));
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  const Contact palm = test::task(scene, "robot/r_palm", "env/wall").contact;
  const Stance three({left, right, palm}), two({left, right});
  SearchOptions options;
  options.contact_reach = 2.0;
  // Default (1): any of two or three contacts may go.
  EXPECT_TRUE(
      offers(enumerate_candidates(scene, data, two, three, options), scene, "robot/l_sole", false));
  EXPECT_TRUE(offers(enumerate_candidates(scene, data, three, three, options), scene,
                     "robot/r_palm", false));
  // 2: from two contacts none is removed, from three any one may be; adding is unaffected.
  options.min_contacts = 2;
  const auto from_two = enumerate_candidates(scene, data, two, three, options);
  EXPECT_FALSE(offers(from_two, scene, "robot/l_sole", false));
  EXPECT_FALSE(offers(from_two, scene, "robot/r_sole", false));
  EXPECT_TRUE(offers(from_two, scene, "robot/r_palm", true));
  const auto from_three = enumerate_candidates(scene, data, three, three, options);
  for (const char* s1 : {"robot/l_sole", "robot/r_sole", "robot/r_palm"})
    EXPECT_TRUE(offers(from_three, scene, s1, false)) << s1;
}

// Two contacts between the same two rigid bodies must turn their normals alike: with the
// cylinder standing on platform A, none of its sides is offered on platform A or on the floor
// (their normals make 90 degrees with its bottom's, the planes' make 0), while its top is not
// offered either (180 vs 0), the pads still are, and the cylinder's sides on nothing else rigid.
TEST(Candidates, RigidBodiesKeepTheAnglesOfTheirContacts) {
  const Scenario scenario =
      load_scenario(test::source_path("scenarios/untuned/dual_arm_handover.yaml"));
  const Scene& scene = scenario.scene;
  const auto data = system_kinematics(scene.system, scenario.initial_configuration);
  const Stance standing = scenario.stance(scenario.initial_stance);
  SearchOptions options;
  options.contact_reach = 10.0;  // every pair within reach: only the rule prunes
  const std::vector<Candidate> list =
      enumerate_candidates(scene, data, standing, scenario.stance(scenario.goal_stance), options);
  int cylinder_on_env = 0, pads_on_cylinder = 0, cylinder_on_platform_b = 0;
  for (const Candidate& c : list) {
    if (!c.add) continue;
    const std::string s1 = scene.surfaces.id(scene.system, c.contact.s1),
                      s2 = scene.surfaces.id(scene.system, c.contact.s2);
    const bool cylinder = s1.rfind("cyl/", 0) == 0 || s2.rfind("cyl/", 0) == 0;
    const bool env = s1.rfind("env/", 0) == 0 || s2.rfind("env/", 0) == 0;
    if (cylinder && env) ++cylinder_on_env;
    if (cylinder && env && (s1 == "env/platform_b" || s2 == "env/platform_b"))
      ++cylinder_on_platform_b;
    if (cylinder && !env) ++pads_on_cylinder;
  }
  // The bottom already stands on A: on the floor and on B (planes parallel to A's) only the
  // bottom itself would keep the angle, and it is in use; so no cylinder surface on the
  // environment at all.
  EXPECT_EQ(cylinder_on_env, 0);
  EXPECT_EQ(cylinder_on_platform_b, 0);
  EXPECT_GT(pads_on_cylinder, 0);
}

}  // namespace
}  // namespace stanceplan
