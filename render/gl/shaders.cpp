#include "render/gl/shaders.h"

namespace stanceplan::render::shaders {
namespace {

// Colours are lit in linear space (gamma 2: square and square root, much cheaper than pow() on
// llvmpipe and visually the same here) for soft, even shading.
const char* kSurface = R"(
in vec3 v_position_W;
in vec3 v_normal_W;
in vec4 v_color;
in vec4 v_light_clip;
uniform vec4 u_color;
uniform int u_vertex_colors;
uniform float u_opacity;
uniform vec3 u_eye_W;
uniform vec3 u_key_dir_W;   // towards the key light
uniform vec3 u_fill_dir_W;  // towards the fill light
out vec4 frag_color;

#ifdef SHADOWS
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_texel;  // one shadow-map texel in texture coordinates
uniform float u_shadow_bias;   // a few millimetres in light depth units

// Fraction of the key light reaching this point: one hardware comparison with bilinear weights
// (2x2 percentage-closer filtering). With millimetre texels that is a clean edge; more taps cost
// real time on llvmpipe, where every pixel of the floor runs this.
float key_visibility(float n_dot_l) {
  vec3 c = v_light_clip.xyz / v_light_clip.w * 0.5 + 0.5;
  // Outside the map (fitted to the subject and its shadow) nothing is known: lit. Sampling the
  // clamped edge instead would smear an edge texel's shadow into an endless band on the floor.
  if (any(lessThan(c.xy, vec2(0.0))) || any(greaterThan(c.xy, vec2(1.0)))) return 1.0;
  float bias = u_shadow_bias * (1.0 + 2.0 * sqrt(1.0 - n_dot_l * n_dot_l) / max(n_dot_l, 0.2));
  return texture(u_shadow_map, vec3(c.xy, min(c.z - bias, 1.0)));
}
#endif

#ifdef FADE
// Geometry far from the subject fades into the background (hides the edges of a finite floor).
uniform vec4 u_background_top;
uniform vec4 u_background_bottom;
uniform float u_viewport_height;
uniform vec2 u_fade_center;
uniform vec2 u_fade_range;  // horizontal distances where fading starts and is complete

vec3 background_here() {
  float h = smoothstep(0.0, 1.0, gl_FragCoord.y / u_viewport_height);
  return mix(u_background_bottom.rgb, u_background_top.rgb, h);
}
#endif

#ifdef GRID
// Lines every u_grid_spacing metres (every 4th stronger), anti-aliased with derivatives.
uniform vec4 u_grid_color;
uniform float u_grid_spacing;
uniform float u_ground_z;

float lines(vec2 p, float spacing, float width) {
  vec2 c = p / spacing;
  vec2 d = abs(fract(c - 0.5) - 0.5) / fwidth(c);
  return 1.0 - clamp(min(d.x, d.y) - 0.5 * width + 0.5, 0.0, 1.0);
}
#endif

void main() {
#ifdef FLOOR_QUAD
  vec4 base = u_color;
#else
  vec4 base = u_vertex_colors == 1 ? v_color : u_color;
#endif
  vec3 n = normalize(v_normal_W);
#ifdef GRID
  vec2 p = v_position_W.xy;
  float minor = lines(p, u_grid_spacing, 1.0), major = lines(p, 4.0 * u_grid_spacing, 1.6);
  float grid = u_grid_color.a * max(0.6 * minor, major);
  if (abs(v_position_W.z - u_ground_z) > 0.002 || abs(n.z) < 0.99) grid = 0.0;
#endif
#ifdef LIT
  vec3 v = normalize(u_eye_W - v_position_W);
  if (dot(n, v) < 0.0) n = -n;  // both faces lit: open meshes and mirrored geometry stay right
  vec3 ambient = mix(vec3(0.16, 0.15, 0.14), vec3(0.42, 0.45, 0.50), 0.5 + 0.5 * n.z);
  float key = max(dot(n, u_key_dir_W), 0.0);
#ifdef SHADOWS
  key *= key_visibility(key);
#endif
  vec3 light = ambient + 1.05 * key * vec3(1.0, 0.98, 0.95);
  vec3 extra = vec3(0.0);
#ifdef SPECULAR
  light += 0.22 * max(dot(n, u_fill_dir_W), 0.0);
  float s = max(dot(n, normalize(u_key_dir_W + v)), 0.0);
  s *= s; s *= s; s *= s; s *= s; s *= s;  // s^32 by squaring
  float r = 1.0 - max(dot(n, v), 0.0);
  extra = vec3(0.22 * s * key + 0.10 * r * r * r);
#endif
  vec3 rgb = sqrt(clamp(base.rgb * base.rgb * light + extra, 0.0, 1.0));
#else
  vec3 rgb = base.rgb;
#endif
#ifdef FADE
  float fade = smoothstep(u_fade_range.x, u_fade_range.y, length(v_position_W.xy - u_fade_center));
#else
  float fade = 0.0;
#endif
#ifdef FLOOR_QUAD
  // The quad is the floor (alpha 1) or only grid lines (alpha 0), and fades by transparency.
  float alpha = base.a + (1.0 - base.a) * grid;
  vec3 c = mix(rgb * base.a, u_grid_color.rgb, grid) / max(alpha, 1e-4);
  frag_color = vec4(c, alpha * (1.0 - fade));
#else
#ifdef GRID
  rgb = mix(rgb, u_grid_color.rgb, grid);
#endif
#ifdef FADE
  rgb = mix(rgb, background_here(), fade);
#endif
  frag_color = vec4(rgb, base.a * u_opacity);
#endif
}
)";

}  // namespace

std::string mesh_vertex() {
  return R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
uniform mat4 u_light_matrix;
out vec3 v_position_W;
out vec3 v_normal_W;
out vec4 v_color;
out vec4 v_light_clip;
void main() {
  vec4 p_W = u_model * vec4(a_position, 1.0);
  v_position_W = p_W.xyz;
  v_normal_W = u_normal_matrix * a_normal;
  v_color = a_color;
  v_light_clip = u_light_matrix * p_W;
  gl_Position = u_view_projection * p_W;
}
)";
}

std::string surface_fragment(unsigned flags) {
  std::string source = "#version 330 core\n";
  if (flags & kLit) source += "#define LIT\n";
  if ((flags & kLit) && (flags & kShadows)) source += "#define SHADOWS\n";
  if ((flags & kLit) && (flags & kSpecular)) source += "#define SPECULAR\n";
  if (flags & kFade) source += "#define FADE\n";
  if (flags & (kGrid | kFloorQuad)) source += "#define GRID\n";
  if (flags & kFloorQuad) source += "#define FLOOR_QUAD\n";
  return source + kSurface;
}

std::string depth_vertex() {
  return R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_light_matrix;
void main() { gl_Position = u_light_matrix * u_model * vec4(a_position, 1.0); }
)";
}

std::string depth_fragment() {
  return R"(#version 330 core
void main() {}
)";
}

std::string background_vertex() {
  return R"(#version 330 core
out float v_height;
void main() {
  vec2 p = vec2((gl_VertexID & 1) * 4.0 - 1.0, (gl_VertexID >> 1) * 4.0 - 1.0);
  v_height = 0.5 * p.y + 0.5;
  gl_Position = vec4(p, 0.999999, 1.0);
}
)";
}

std::string background_fragment() {
  return R"(#version 330 core
in float v_height;
uniform vec4 u_top;
uniform vec4 u_bottom;
out vec4 frag_color;
void main() {
  frag_color = vec4(mix(u_bottom.rgb, u_top.rgb, smoothstep(0.0, 1.0, v_height)), 1.0);
}
)";
}

}  // namespace stanceplan::render::shaders
