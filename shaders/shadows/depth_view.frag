#version 330 core
// A light's depth map, as stored (raw) or as distance (linear), zoomed about a chosen centre
// (hover the viewport for the value of each pixel). A cube map is unrolled as a cross:        +Y
//             -X  +Z  +X  -Z
//                 -Y
#include "common/output.glsl"
#include "shadows/shadow_filters.glsl"

in vec2 v_uv;
uniform ShadowLight u_key;
uniform sampler2D u_keyMap;
uniform samplerCube u_keyCube;
uniform vec2 u_aspect;  // viewport aspect correction, so texels stay square
uniform float u_zoom;
uniform vec2 u_centre;  // the map point shown at the middle of the viewport
out vec4 o_color;

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
    o_color = vec4(0.02, 0.02, 0.03, 1.0);
    return;
  }
  z = texture(u_keyCube, dir).r;
#else
  if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) {
    o_color = vec4(0.02, 0.02, 0.03, 1.0);
    return;
  }
  z = texture(u_keyMap, uv).r;
#endif
#ifdef LINEAR_DEPTH
  float d = storedToLinear(KEY_TYPE, u_key, z);
  z = (d - u_key.nearPlane) / (u_key.farPlane - u_key.nearPlane);
#endif
  o_color = vec4(vec3(z), 1.0);  // depth is data: shown as stored, no sRGB curve
}
