#version 330 core
// Shadows lab, depth-range fit (labs/shadows/depth_range.h): one texel per 8x8 block of the level
// before, holding the nearest and farthest view depth in it. The first pass reads the camera's
// depth buffer and turns window depth into view depth; the background (depth 1) holds nothing.
// The block's (min, max) is (1e30, -1e30) where it holds no surface at all.
#ifdef FROM_DEPTH
uniform sampler2D u_depth;
uniform vec2 u_planes;  // the camera's near and far planes
#else
uniform sampler2D u_level;
#endif
uniform vec2 u_size;  // the size of what this pass reads, in texels

out vec2 o_range;

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 8, last = ivec2(u_size) - 1;
  vec2 range = vec2(1e30, -1e30);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      ivec2 p = min(base + ivec2(x, y), last);  // past the edge: the edge texel again
#ifdef FROM_DEPTH
      float z = texelFetch(u_depth, p, 0).r;
      // Window depth of a perspective projection back to view depth: n f / (f - z (f - n)).
      float d = u_planes.x * u_planes.y / (u_planes.y - z * (u_planes.y - u_planes.x));
      if (z < 1.0) range = vec2(min(range.x, d), max(range.y, d));
#else
      vec2 r = texelFetch(u_level, p, 0).rg;
      range = vec2(min(range.x, r.x), max(range.y, r.y));
#endif
    }
  }
  o_range = range;
}
