#version 330 core
// Shadows lab's GPU truth: shadow rays from each pixel through a BVH of the scene's triangles
// (app/measure/bvh.h, flattened into two float textures and walked without a stack), added into
// an accumulator.
// Pass 0 also traces the hard ray to the light's centre; every pass traces u_diskCount stratified
// points of the light's disk (the same points, in another order, as the Embree truth's 8 x 8) and
// adds their sum: several samples a draw, so that the additive blend into a float target, slow
// where a GPU has few raster back ends, happens once for all of them. A pass's rays walk the BVH
// together (blockedRays).
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
uniform vec2 u_disks[16];          // this pass's points of the unit disk
uniform int u_diskCount;           // how many of them (1..16)
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
bool hitsTriangle(vec3 a, vec3 e1, vec3 e2, vec3 origin, vec3 dir, float tMax) {
  vec3 p = cross(dir, e2);
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

// The rays of one pixel's pass, all from one origin: the hard ray (pass 0) and the disk samples.
#define MAX_RAYS 17
vec3 g_dir[MAX_RAYS];
vec3 g_invDir[MAX_RAYS];
float g_tMax[MAX_RAYS];

// Which of rays 0..count-1 meet anything between the origin and origin + dir * tMax (bit k for
// ray k), all in one walk: the nodes in depth-first order with no stack. A node whose box some
// ray still unblocked enters leads to the next node (an inner node's first child); one that none
// enters, or a leaf whose triangles are tested, leads past its subtree (skip). Indices only grow,
// so no node is visited twice and the walk ends at u_nodeCount, or sooner when every ray is
// blocked. The rays of a pixel head for one light and visit nearly the same nodes, so a walk for
// all of them reads each node and triangle once where a walk per ray read them count times. A ray
// taken into a child whose parent it missed only meets more exact triangle tests: each ray's
// answer is the one a walk of its own gives.
uint blockedRays(vec3 origin, int count) {
  uint pending = (1u << uint(count)) - 1u, blocked = 0u;
  int node = 0;
  for (int steps = 0; node < u_nodeCount && pending != 0u; ++steps) {
    if (steps >= u_maxSteps) {
      g_gaveUp = true;
      return blocked;
    }
    vec4 lo = texelAt(u_bvhNodes, 2 * node), hi = texelAt(u_bvhNodes, 2 * node + 1);
    uint link = floatBitsToUint(hi.w);
    int skip = int(link & 0xFFFFFFu), triangles = int(link >> 24);
    uint entering = 0u;
    for (int k = 0; k < count; ++k)
      if ((pending & (1u << uint(k))) != 0u && entersBox(lo.xyz, hi.xyz, origin, g_invDir[k], g_tMax[k]))
        entering |= 1u << uint(k);
    if (entering == 0u) {
      node = skip;
      continue;
    }
    if (triangles == 0) {
      ++node;
      continue;
    }
    int first = int(floatBitsToUint(lo.w));
    for (int i = first; i < first + triangles && entering != 0u; ++i) {
      vec3 a = texelAt(u_bvhTriangles, 3 * i).xyz;
      vec3 e1 = texelAt(u_bvhTriangles, 3 * i + 1).xyz - a, e2 = texelAt(u_bvhTriangles, 3 * i + 2).xyz - a;
      for (int k = 0; k < count; ++k) {
        uint bit = 1u << uint(k);
        if ((entering & bit) != 0u && hitsTriangle(a, e1, e2, origin, g_dir[k], g_tMax[k])) {
          blocked |= bit;
          entering &= ~bit;
        }
      }
    }
    pending &= ~blocked;
    node = skip;
  }
  return blocked;
}

void basis(vec3 n, out vec3 t, out vec3 b) {
  t = normalize(cross(abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0), n));
  b = cross(n, t);
}

// Ray k: from `origin` to the point `d` of the light's unit disk (its centre for the hard ray).
void aimRay(int k, vec3 origin, vec2 d) {
  vec3 t, b;
  if (u_lightType == 0) {
    basis(-u_lightDirection, t, b);
    g_dir[k] = normalize(-u_lightDirection + (t * d.x + b * d.y) * u_lightRadius);
    g_tMax[k] = 1e30;
  } else {
    basis(normalize(u_lightPosition - origin), t, b);
    g_dir[k] = u_lightPosition + (t * d.x + b * d.y) * u_lightRadius - origin;
    g_tMax[k] = 1.0;  // stop at the light
  }
  g_invDir[k] = 1.0 / g_dir[k];
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_positions, p, 0);
  if (position.w <= 0.5) {
    o_sum = vec4(0.0);
    return;
  }
  vec3 origin = position.xyz + texelFetch(u_normals, p, 0).xyz * u_epsilon;
#ifdef ONE_RAY
  // A light of no size: the hard ray is every sample (one pass).
  aimRay(0, origin, vec2(0.0));
  float hard = blockedRays(origin, 1) == 0u ? 1.0 : 0.0;
  float area = float(u_diskCount) * hard;
#else
  // Ray 0 the hard ray in pass 0; then the disk's.
  bool hardRay = u_pass == 0;
  int count = 0;
  if (hardRay) aimRay(count++, origin, vec2(0.0));
  for (int k = 0; k < u_diskCount; ++k) aimRay(count++, origin, u_disks[k]);
  uint blocked = blockedRays(origin, count);
  float hard = hardRay && (blocked & 1u) == 0u ? 1.0 : 0.0;
  float area = 0.0;
  for (int k = hardRay ? 1 : 0; k < count; ++k) area += (blocked & (1u << uint(k))) == 0u ? 1.0 : 0.0;
#endif
  o_sum = vec4(hard, area, area, (u_pass == 0 ? 1.0 : 0.0) + (g_gaveUp ? 1024.0 : 0.0));  // 0/1 samples: sum of squares = sum
}
