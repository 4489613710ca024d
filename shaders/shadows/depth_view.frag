#version 330 core
// A light's depth map, as stored (raw) or as distance (linear), zoomed about a chosen centre
// (hover the viewport for the value of each pixel). A cube map is unrolled as a cross:        +Y
//             -X  +Z  +X  -Z
//                 -Y
// Linear views (and every cube view: a cube stores distance already) stretch the distances the
// scene occupies, u_range, over black..white, so the picture shows the scene's shape rather than
// one grey; texels where nothing was drawn are shown in dark blue, not white.
#include "common/output.glsl"
#include "shadows/shadow_filters.glsl"

in vec2 v_uv;
uniform ShadowLight u_key;
uniform sampler2DArray u_keyMap;
uniform samplerCube u_keyCube;
uniform vec2 u_aspect;  // viewport aspect correction, so texels stay square
uniform float u_zoom;
uniform vec2 u_centre;  // the map point shown at the middle of the viewport
uniform vec2 u_range;   // the scene's nearest and farthest distance from the light
out vec4 o_color;

const vec4 kOutside = vec4(0.02, 0.02, 0.03, 1.0);
const vec4 kEmpty = vec4(0.05, 0.08, 0.25, 1.0);

void main() {
  vec2 uv = (v_uv - 0.5) * u_aspect / u_zoom + u_centre;
  float z;
#if KEY_TYPE == LIGHT_POINT
  vec2 cell = floor(vec2(uv.x * 4.0, uv.y * 3.0));
  vec2 f = fract(vec2(uv.x * 4.0, uv.y * 3.0)) * 2.0 - 1.0;
  vec3 dir;
  if (uv.x < 0.0 || uv.x >= 1.0 || uv.y < 0.0 || uv.y >= 1.0) dir = vec3(0.0);
  else if (cell.y == 1.0 && cell.x == 0.0) dir = vec3(-1.0, f.y, f.x);
  else if (cell.y == 1.0 && cell.x == 1.0) dir = vec3(f.x, f.y, 1.0);
  else if (cell.y == 1.0 && cell.x == 2.0) dir = vec3(1.0, f.y, -f.x);
  else if (cell.y == 1.0 && cell.x == 3.0) dir = vec3(-f.x, f.y, -1.0);
  else if (cell.y == 2.0 && cell.x == 1.0) dir = vec3(f.x, 1.0, -f.y);
  else if (cell.y == 0.0 && cell.x == 1.0) dir = vec3(f.x, -1.0, f.y);
  else dir = vec3(0.0);
  if (dir == vec3(0.0)) {
    o_color = kOutside;
    return;
  }
  z = textureLod(u_keyCube, dir, 0.0).r;
#else
  if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) {
    o_color = kOutside;
    return;
  }
  z = textureLod(u_keyMap, vec3(uv, u_key.layer), 0.0).r;
#endif
  if (z >= 1.0) {
    o_color = kEmpty;
    return;
  }
#if defined(LINEAR_DEPTH) || KEY_TYPE == LIGHT_POINT
  float d = storedToLinear(KEY_TYPE, u_key, z);
  z = clamp((d - u_range.x) / max(u_range.y - u_range.x, 1e-30), 0.0, 1.0);
#endif
  o_color = vec4(vec3(z), 1.0);  // depth is data: shown as stored, no sRGB curve
}
