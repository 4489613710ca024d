#version 330 core
// Shadows lab's GPU truth: one shadow ray per pixel per pass through a BVH of the scene's
// triangles (app/measure/bvh.h, flattened into two float textures and walked without a stack),
// added into an accumulator.
// Pass 0 also traces the hard ray to the light's centre; every pass traces u_diskCount stratified
// points of the light's disk (the same points, in another order, as the Embree truth's 8 x 8) and
// adds their sum: several samples a draw, so that the additive blend into a float target, slow
// where a GPU has few raster back ends, happens once for all of them.
//   out: R the hard visibility (pass 0 only), G the sum of the area samples, B of their squares,
//        A coverage (pass 0), plus 1024 where a ray gave up (a traversal past u_maxSteps: a bound
//        that cannot hang)
uniform sampler2D u_positions;  // xyz world, w > 0.5 where a surface faces the light
uniform sampler2D u_normals;
uniform sampler2D u_bvhNodes;      // two texels a node, depth-first: (min, first), (max, skip | count << 24)
uniform sampler2D u_bvhTriangles;  // three texels a triangle: a, b, c
uniform int u_bvhWidthLog2;        // texels per row of both: a power of two
uniform int u_lightType;           // 0 directional, else a position (spot, point)
uniform vec3 u_lightPosition;
uniform vec3 u_lightDirection;     // from the light into the scene
uniform float u_lightRadius;       // world units (directional: tangent of the angular radius)
uniform vec2 u_disks[8];           // this pass's points of the unit disk
uniform int u_diskCount;           // how many of them (1..8)
uniform int u_pass;
uniform float u_epsilon;           // lifts ray origins off their surface along the normal
uniform int u_nodeCount;           // where the walk ends
uniform int u_maxSteps;            // nodes a ray may visit: the node count (each is visited once at most)
out vec4 o_sum;

bool g_gaveUp = false;  // a ray ran out of steps: counted as lit, and the pixel is flagged (A += 1024)

vec4 texelAt(sampler2D s, int i) {
  return texelFetch(s, ivec2(i & ((1 << u_bvhWidthLog2) - 1), i >> u_bvhWidthLog2), 0);
}

bool entersBox(vec3 lo, vec3 hi, vec3 origin, vec3 invDir, float tMax) {
  vec3 t0 = (lo - origin) * invDir, t1 = (hi - origin) * invDir;
  vec3 near = min(t0, t1), far = max(t0, t1);
  float enter = max(max(near.x, near.y), max(near.z, 0.0));
  float exit = min(min(far.x, far.y), min(far.z, tMax));
  return enter <= exit;
}

// Moller-Trumbore, as intersectTriangle() on the CPU.
bool hitsTriangle(int t, vec3 origin, vec3 dir, float tMax) {
  vec3 a = texelAt(u_bvhTriangles, 3 * t).xyz, b = texelAt(u_bvhTriangles, 3 * t + 1).xyz,
       c = texelAt(u_bvhTriangles, 3 * t + 2).xyz;
  vec3 e1 = b - a, e2 = c - a, p = cross(dir, e2);
  float det = dot(e1, p);
  if (!(abs(det) > 1e-30)) return false;
  float inv = 1.0 / det;
  vec3 s = origin - a;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  vec3 q = cross(s, e1);
  float v = dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  float hit = dot(e2, q) * inv;
  return hit > 0.0 && hit < tMax;
}

// Anything between origin and origin + dir * tMax: a walk of the nodes in depth-first order with
// no stack. Entering a node's box leads to the next node (an inner node's first child); missing
// it, or a leaf whose triangles are tested, leads past its subtree (skip). Indices only grow, so
// no node is visited twice and the walk ends at u_nodeCount.
bool occluded(vec3 origin, vec3 dir, float tMax) {
  vec3 invDir = 1.0 / dir;
  int node = 0;
  for (int steps = 0; node < u_nodeCount; ++steps) {
    if (steps >= u_maxSteps) {
      g_gaveUp = true;
      return false;
    }
    vec4 lo = texelAt(u_bvhNodes, 2 * node), hi = texelAt(u_bvhNodes, 2 * node + 1);
    uint link = floatBitsToUint(hi.w);
    int skip = int(link & 0xFFFFFFu), count = int(link >> 24);
    if (!entersBox(lo.xyz, hi.xyz, origin, invDir, tMax)) {
      node = skip;
      continue;
    }
    if (count == 0) {
      ++node;
      continue;
    }
    int first = int(floatBitsToUint(lo.w));
    for (int i = first; i < first + count; ++i)
      if (hitsTriangle(i, origin, dir, tMax)) return true;
    node = skip;
  }
  return false;
}

void basis(vec3 n, out vec3 t, out vec3 b) {
  t = normalize(cross(abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0), n));
  b = cross(n, t);
}

// 1 when the ray from `origin` to the point `d` of the light's unit disk gets through.
float reaches(vec3 origin, vec2 d) {
  vec3 t, b;
  if (u_lightType == 0) {
    basis(-u_lightDirection, t, b);
    return occluded(origin, normalize(-u_lightDirection + (t * d.x + b * d.y) * u_lightRadius), 1e30) ? 0.0 : 1.0;
  }
  basis(normalize(u_lightPosition - origin), t, b);
  vec3 target = u_lightPosition + (t * d.x + b * d.y) * u_lightRadius;
  return occluded(origin, target - origin, 1.0) ? 0.0 : 1.0;  // stop at the light
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_positions, p, 0);
  if (position.w <= 0.5) {
    o_sum = vec4(0.0);
    return;
  }
  vec3 origin = position.xyz + texelFetch(u_normals, p, 0).xyz * u_epsilon;
  float hard = u_pass == 0 ? reaches(origin, vec2(0.0)) : 0.0;
  float area = 0.0, areaSq = 0.0;
  for (int k = 0; k < u_diskCount; ++k) {
    float a = u_lightRadius > 0.0 ? reaches(origin, u_disks[k]) : (u_pass == 0 ? hard : reaches(origin, vec2(0.0)));
    area += a;
    areaSq += a * a;
  }
  o_sum = vec4(hard, area, areaSq, (u_pass == 0 ? 1.0 : 0.0) + (g_gaveUp ? 1024.0 : 0.0));
}
