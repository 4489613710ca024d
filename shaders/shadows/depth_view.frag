#version 330 core
// A light's depth map, as stored (raw) or as distance (linear), zoomed about a chosen centre
// (hover the viewport for the value of each pixel). A cube map is unrolled as a cross:        +Y
//             -X  +Z  +X  -Z
//                 -Y
// Linear views (and every cube view: a cube stores distance already) stretch the distances the
// scene occupies, u_range, over black..white, so the picture shows the scene's shape rather than
// one grey; texels where nothing was drawn are shown in dark blue, not white. Each cube face is
// zoomed to the square of it the scene projects to (frame_faces), and only the faces that see the
// scene are shown, side by side: a scene beside a point light fills a corner of one or two faces,
// and the whole cross would be blue. A face's border is the brighter the more it is zoomed.
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
uniform vec3 u_faceWindow[6];  // cube faces, in the cross's order: the shown square (centre, half size)
uniform int u_faceCount;       // frame_faces: how many faces see the scene (0: the whole cross)
uniform int u_faces[6];        // ... and which, in the cross's order
out vec4 o_color;

const vec4 kOutside = vec4(0.02, 0.02, 0.03, 1.0);
const vec4 kEmpty = vec4(0.05, 0.08, 0.25, 1.0);
const vec4 kBlindFace = vec4(0.03, 0.04, 0.12, 1.0);

void main() {
  vec2 uv = (v_uv - 0.5) * u_aspect / u_zoom + u_centre;
  float z;
#if KEY_TYPE == LIGHT_POINT
  int face = -1;
  vec2 f, toEdge;
  if (u_faceCount > 0) {
    // Only the faces that see the scene, in a row (two rows past three), each one square cell.
    int cols = min(u_faceCount, 3), rows = (u_faceCount + 2) / 3;
    vec2 grid = vec2(uv.x * float(cols), uv.y * float(rows));
    vec2 cell = floor(grid);
    f = fract(grid) * 2.0 - 1.0;
    toEdge = (1.0 - abs(f)) / max(fwidth(f), vec2(1e-6));  // pixels to the cell's border
    int k = int(cell.x) + cols * (rows - 1 - int(cell.y));
    if (uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0 && k < u_faceCount) face = u_faces[k];
  } else {
    vec2 cell = floor(vec2(uv.x * 4.0, uv.y * 3.0));
    f = fract(vec2(uv.x * 4.0, uv.y * 3.0)) * 2.0 - 1.0;
    toEdge = (1.0 - abs(f)) / max(fwidth(f), vec2(1e-6));
    if (uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0) {
      if (cell.y == 1.0) face = int(cell.x);  // -X +Z +X -Z
      else if (cell.x == 1.0) face = cell.y == 2.0 ? 4 : 5;  // +Y above, -Y below
    }
  }
  if (face < 0) {
    o_color = kOutside;
    return;
  }
  vec3 window = u_faceWindow[face];
  if (window.z <= 0.0) {
    o_color = kBlindFace;
    return;
  }
  // A zoomed face's border, two pixels wide: brighter the more the face is zoomed.
  if (min(toEdge.x, toEdge.y) < 2.0 && window.z < 1.0) {
    o_color = vec4(mix(vec3(0.25, 0.3, 0.45), vec3(0.95, 0.75, 0.2), 1.0 - window.z), 1.0);
    return;
  }
  f = window.xy + f * window.z;
  vec3 dir;
  if (face == 0) dir = vec3(-1.0, f.y, f.x);
  else if (face == 1) dir = vec3(f.x, f.y, 1.0);
  else if (face == 2) dir = vec3(1.0, f.y, -f.x);
  else if (face == 3) dir = vec3(-f.x, f.y, -1.0);
  else if (face == 4) dir = vec3(f.x, 1.0, -f.y);
  else dir = vec3(f.x, -1.0, f.y);
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
