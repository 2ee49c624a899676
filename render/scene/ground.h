#pragma once
// Where a picture's ground is: the environment's own floor when it has one under the whole
// subject, otherwise a plane the renderer draws under the lowest point of the scene, so that the
// ground never hides geometry (an environment whose floor is at z = -0.9). The rule, in full, is
// in docs/RENDERING.md ("The ground").
#include "render/scene/draw_list.h"

namespace stanceplan::render {

// Tolerances of the rule, in metres or as ratios.
struct GroundRule {
  double slab_ratio = 0.1;       // a floor slab is at most this thick per metre of its smaller side
  double top_tolerance = 0.01;   // slabs whose tops are this close together form one floor
  double sink_tolerance = 0.05;  // geometry this far into the floor still stands on it
  double margin = 0.5;           // the floor must reach this far around the subject's footprint
};

// The ground of a frame from its scene geometry (robots, objects, environment: call it before
// contact overlays are added). An environment provides the floor when (1) some of its items are
// horizontal slabs (bounding box at most slab_ratio as thick as its smaller side), (2) no other
// geometry reaches more than sink_tolerance below the top of the lowest slab, and (3) the slabs
// whose tops lie at that height cover the subject's footprint (the horizontal bounding box of the
// robots and objects) grown by `margin` on every side. Then the ground is at that top, drawn by
// the environment. Otherwise the renderer's ground plane is at the lowest point of all geometry,
// or at z = 0 (the URDF convention) when everything is above it.
Ground find_ground(const DrawList& list, const GroundRule& rule = {});

}  // namespace stanceplan::render
