#pragma once
// What a picture shows and how it looks. The defaults are tuned for paper figures of a humanoid
// scene (sizes in metres); tests switch off the decorations to assert exact pixel values.
#include "render/image/color.h"

namespace stanceplan::render {

struct RenderStyle {
  // The cheaper look for live snapshots of a running search: no multisampling (edges smoothed
  // after rendering instead) and a coarser shadow map; everything else as in figures. About
  // two thirds of the rendering time of the default (figure) style; without shadows, less again.
  static RenderStyle preview() {
    RenderStyle style;
    style.samples = 1;
    style.shadow_map_size = 512;
    return style;
  }

  // Quality.
  int samples = 4;             // multisample anti-aliasing (1 = off; llvmpipe supports 4)
  bool edge_smoothing = true;  // without multisampling: post-process anti-aliasing (cheaper)
  bool shadows = true;         // shadow map from the key light, fitted to the subject's shadow
  int shadow_map_size = 1024;

  // Background and ground.
  bool background_gradient = true;
  Color background_top = rgb_hex(0xdfe6ee);
  Color background_bottom = rgb_hex(0xfbfbfc);  // also the flat background when no gradient
  // The ground is placed per frame (render/scene/ground.h, docs/RENDERING.md): an environment's
  // floor under the whole subject, else a plane under the lowest point of the scene.
  bool grid = true;            // grid lines on the ground
  double grid_spacing = 0.25;  // minor lines; every 4th line is a major one
  Color grid_color = rgb_hex(0x6f7884, 0.35f);
  bool floor = true;  // the ground plane is opaque when no environment provides the floor
  Color floor_color = rgb_hex(0xeceae6);

  // Geometry.
  bool collision_geometry = false;  // draw <collision> instead of <visual> geometry
  // Environment geometry between the camera and the robots (a wall in front of the robot) is
  // drawn see-through at this opacity around them and not over them (a cutaway); 1 disables it.
  float occluder_opacity = 0.3f;
  Color default_color = rgb_hex(0xb4b8bf);  // links with no colour in the URDF or mesh
  bool lighting = true;                     // false: flat colours (tests)

  // Contact information.
  bool contacts = true;
  Color loaded_contact = rgb_hex(0x1f9e5a);    // contact carrying force
  Color unloaded_contact = rgb_hex(0xf0a202);  // touching, no force (the larger stance)
  double contact_ring_width = 0.012;
  bool forces = true;
  Color force_color = rgb_hex(0xd62839);
  double force_scale = 0.0;       // metres per newton; 0: the largest force of the frame is 0.3 m
  double force_max_length = 0.3;  // used by the automatic scale
  double force_radius = 0.006;    // arrow shaft radius
  bool friction_cones = false;
  double friction = 1.0;  // Coulomb coefficient of the cones
  double cone_height = 0.08;
  Color cone_color = rgb_hex(0x3a7bd5, 0.28f);
  bool center_of_mass = true;  // floating robots: a sphere, and its projection on the ground
  Color com_color = rgb_hex(0x222831);
  double com_radius = 0.03;
  bool support_polygon = true;  // convex hull of the loaded contact points lying on the ground
  Color support_color = rgb_hex(0x1f9e5a, 0.22f);
  // Overlays hidden behind geometry are still drawn, faded to this opacity ("x-ray"), so that
  // forces under a foot or a centre of mass inside the body stay readable.
  float xray_opacity = 0.45f;

  // Text (drawn on the image after rendering).
  bool caption = true;
  bool legend = true;
  double text_scale = 1.0;  // relative to a size chosen from the image height
};

}  // namespace stanceplan::render
