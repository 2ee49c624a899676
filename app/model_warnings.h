#pragma once
// The line a command that loads a scenario prints on stderr for each model whose inertia tensors
// the URDF loader ignored (planner/model/ignored_inertia.h): the planner library never prints,
// the models carry the list.
#include <iosfwd>

#include "planner/scene/scene.h"

namespace stanceplan::app {

// "stanceplan: warning: FILE: inertia of 2 links ignored (not used by the statics): a (FAULT),
// b (FAULT)", once per URDF file however many entities load it.
void print_model_warnings(const Scene& scene, std::ostream& err);

}  // namespace stanceplan::app
