#pragma once
// Scenario file text for tests that write scenarios with faults at known lines.
#include <string>

#include "tests/support/paths.h"

namespace stanceplan::test {

// Lines 1-13 of a scenario: the humanoid (base at [0, 0, 0.9], `joints` a YAML flow map of joint
// values) and the environment assets/environments/ENVIRONMENT; stances and the rest follow.
inline std::string humanoid_on(const std::string& environment, const std::string& joints) {
  const std::string assets = source_path("assets");
  const std::string env = assets + "/environments/" + environment + "/" + environment;
  // clang-format off
  return "format: stanceplan/scenario@1\n"                                           // 1
         "entities:\n"                                                               // 2
         "  - name: robot\n"                                                         // 3
         "    kind: floating\n"                                                      // 4
         "    urdf: " + assets + "/robots/humanoid/humanoid.urdf\n"                  // 5
         "    surfaces: " + assets + "/robots/humanoid/humanoid.surfaces.yaml\n"     // 6
         "    configuration:\n"                                                      // 7
         "      base_position: [0, 0, 0.9]\n"                                        // 8
         "      joints: " + joints + "\n"                                            // 9
         "  - name: env\n"                                                           // 10
         "    kind: environment\n"                                                   // 11
         "    urdf: " + env + ".urdf\n"                                              // 12
         "    surfaces: " + env + ".surfaces.yaml\n";                                // 13
  // clang-format on
}

}  // namespace stanceplan::test
