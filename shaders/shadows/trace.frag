#version 330 core
// Shadows lab's GPU truth: shadow rays from each pixel through a BVH of the scene's triangles
// (app/measure/bvh.h, flattened into two float textures and walked without a stack), added into
// an accumulator.
// Pass 0 also traces the hard ray to the light's centre; every pass traces u_diskCount stratified
// points of the light's disk (the same points, in another order, as the Embree truth's 8 x 8) and
// adds their sum: several samples a draw, so that the additive blend into a float target, slow
// where a GPU has few raster back ends, happens once for all of them. A pass's rays walk the BVH
// together, WALK_WIDTH of them a walk (blockedRays).
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

// Whether the ray from the origin along 1 / invDir enters the box [lo, hi] (corners relative to
// the origin: shared by every ray of a walk) before tMax.
bool entersBox(vec3 lo, vec3 hi, vec3 invDir, float tMax) {
  vec3 t0 = lo * invDir, t1 = hi * invDir;
  vec3 near = min(t0, t1), far = max(t0, t1);
  float enter = max(max(near.x, near.y), max(near.z, 0.0));
  float exit = min(min(far.x, far.y), min(far.z, tMax));
  return enter <= exit;
}

// Moller-Trumbore, as intersectTriangle() on the CPU, for a triangle (a, a + e1, a + e2) and a
// ray from the origin: s = origin - a, q = cross(s, e1) and tq = dot(e2, q) depend on the
// triangle and the origin alone, so a walk's rays share them.
bool hitsTriangle(vec3 e1, vec3 e2, vec3 s, vec3 q, float tq, vec3 dir, float tMax) {
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (!(abs(det) > 1e-30)) return false;
  float inv = 1.0 / det;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  float v = dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  float hit = tq * inv;
  return hit > 0.0 && hit < tMax;
}

// Rays that walk the BVH together: a compile-time count, so that every loop over them unrolls and
// their directions live in registers (a loop to a count known only at run time indexes them in
// memory, which a GPU reads as slowly as the tree itself). The rays of a pixel share their origin,
// and the walk its length: to the light (directions reach it at t = 1) or, for a directional
// light, without end.
#ifndef WALK_WIDTH
#define WALK_WIDTH 16
#endif
vec3 g_dir[WALK_WIDTH];
vec3 g_invDir[WALK_WIDTH];
float g_tMax;

#ifdef CONE_CULL
// The rays of a walk leave one origin within a cone (axis g_axis, half-angle of cosine g_cos and
// sine g_sin) and end within g_reach of it: a node whose bounding sphere lies outside that cone is
// entered by none of them, and one test stands for all of their box tests.
vec3 g_axis;
float g_cos, g_sin, g_reach;

void fitCone(int count) {
  vec3 sum = vec3(0.0);
  g_reach = 0.0;
  for (int k = 0; k < WALK_WIDTH; ++k)
    if (k < count) {
      sum += normalize(g_dir[k]);
      g_reach = max(g_reach, length(g_dir[k]) * g_tMax);
    }
  g_axis = normalize(sum);
  float c = 1.0;
  for (int k = 0; k < WALK_WIDTH; ++k)
    if (k < count) c = min(c, dot(normalize(g_dir[k]), g_axis));
  g_cos = c - 1e-4;  // wider by the rounding of the directions
  g_sin = sqrt(max(1.0 - g_cos * g_cos, 0.0));
}

// True only where no ray of the walk can enter the box [lo, hi] (corners relative to the origin):
// its bounding sphere is farther from the cone's side than its radius, or beyond every ray's end.
// The margins are relative, for scenes at any scale; a cone wider than about 84 degrees rejects
// nothing.
bool outsideCone(vec3 lo, vec3 hi) {
  vec3 centre = 0.5 * (lo + hi);
  float radius = 0.5 * length(hi - lo), away = length(centre);
  float along = dot(centre, g_axis), across = length(centre - along * g_axis);
  float slack = 1.001 * radius + 1e-5 * away;
  return (g_cos > 0.1 && across * g_cos - along * g_sin > slack) || away - slack > g_reach * 1.0001;
}
#endif

// Which of rays 0..count-1 (count <= WALK_WIDTH) meet anything between the origin and
// origin + dir * g_tMax (bit k for ray k), all in one walk: the nodes in depth-first order with no
// stack. A node whose box some ray still unblocked enters leads to the next node (an inner node's
// first child); one that none enters, or a leaf whose triangles are tested, leads past its subtree
// (skip). Indices only grow, so no node is visited twice and the walk ends at u_nodeCount, or
// sooner when every ray is blocked. The rays of a pixel head for one light and visit nearly the
// same nodes, so a walk for all of them reads each node and triangle once where a walk per ray
// read them count times. A ray taken into a child whose parent it missed only meets more exact
// triangle tests: each ray's answer is the one a walk of its own gives.
uint blockedRays(vec3 origin, int count) {
#ifdef CONE_CULL
  fitCone(count);
#endif
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
    vec3 boxLo = lo.xyz - origin, boxHi = hi.xyz - origin;
    uint entering = 0u;
#ifdef CONE_CULL
    if (!outsideCone(boxLo, boxHi))
#endif
    for (int k = 0; k < WALK_WIDTH; ++k)
      if ((pending & (1u << uint(k))) != 0u && entersBox(boxLo, boxHi, g_invDir[k], g_tMax)) entering |= 1u << uint(k);
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
      vec3 s = origin - a, q = cross(s, e1);
      float tq = dot(e2, q);
      for (int k = 0; k < WALK_WIDTH; ++k) {
        uint bit = 1u << uint(k);
        if ((entering & bit) != 0u && hitsTriangle(e1, e2, s, q, tq, g_dir[k], g_tMax)) {
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

// Ray k of a walk: from `origin` to the point `d` of the light's unit disk (its centre for the
// hard ray).
void aimRay(int k, vec3 origin, vec2 d) {
  vec3 t, b;
  if (u_lightType == 0) {
    basis(-u_lightDirection, t, b);
    g_dir[k] = normalize(-u_lightDirection + (t * d.x + b * d.y) * u_lightRadius);
  } else {
    basis(normalize(u_lightPosition - origin), t, b);
    g_dir[k] = u_lightPosition + (t * d.x + b * d.y) * u_lightRadius - origin;
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
  g_tMax = u_lightType == 0 ? 1e30 : 1.0;
#ifdef ONE_RAY
  // A light of no size: the hard ray is every sample (one pass).
  aimRay(0, origin, vec2(0.0));
  float hard = blockedRays(origin, 1) == 0u ? 1.0 : 0.0;
  float area = float(u_diskCount) * hard;
#else
  // The pass's rays, WALK_WIDTH a walk: in pass 0 the hard ray first, then the disk's.
  bool hardRay = u_pass == 0;
  int rays = u_diskCount + (hardRay ? 1 : 0), firstDisk = hardRay ? 1 : 0;
  float hard = 0.0, area = 0.0;
  for (int first = 0; first < rays; first += WALK_WIDTH) {
    int count = min(WALK_WIDTH, rays - first);
    for (int k = 0; k < WALK_WIDTH; ++k)
      if (k < count) aimRay(k, origin, first + k < firstDisk ? vec2(0.0) : u_disks[clamp(first + k - firstDisk, 0, 15)]);
    uint blocked = blockedRays(origin, count);
    for (int k = 0; k < WALK_WIDTH; ++k) {
      float lit = k < count && (blocked & (1u << uint(k))) == 0u ? 1.0 : 0.0;
      if (first + k < firstDisk) hard = lit;
      else area += lit;
    }
  }
#endif
  o_sum = vec4(hard, area, area, (u_pass == 0 ? 1.0 : 0.0) + (g_gaveUp ? 1024.0 : 0.0));  // 0/1 samples: sum of squares = sum
}
