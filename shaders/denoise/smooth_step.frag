#version 330 core
// Denoising on the GPU: one explicit step for every vertex, a fragment each (labs/denoise/gpu_smoother.h).
// Vertex v lives at texel (v % 1024, v / 1024) of every per-vertex texture, and entry i of a list
// at (i % 1024, i / 1024): one width, a power of two, so the address is a mask and a shift. Its one-ring comes
// from a compressed-row layout: u_ranges gives where v's neighbours and its faces start in two
// lists and how many there are; u_ring gives each neighbour j and the vertices opposite the edge
// (v, j) (-1: none), whose angles make the cotangent weight; u_faces gives each face's other two
// corners in winding order, for the vertex normal. Weights and normal follow laplacian.cpp's
// edgeWeights() and normalsOf() rule for rule, so the CPU and the GPU smooth the same mesh alike.
// Writes the new position in .xyz and this vertex's energy term, measured before the step, in .w.
#include "denoise/laplacian_step.glsl"

uniform sampler2D u_positions;  // .xyz, relative to the mesh's centre
uniform isampler2D u_ranges;    // ring start, ring count, face start, face count
uniform isampler2D u_ring;      // neighbour, opposite vertex, the other opposite vertex
uniform isampler2D u_faces;     // the face's next corner, the one after
uniform int u_vertexCount;
uniform float u_lambda;
out vec4 o_position;

ivec2 texelOf(int index) { return ivec2(index & 1023, index >> 10); }
vec3 positionOf(int v) { return texelFetch(u_positions, texelOf(v), 0).xyz; }

// Both lists are read four entries at a time, every fetch of a group issued before any result is
// used: a GPU then waits for the group's memory once, not once per entry (twice as fast on an
// H200 at 870,000 vertices). Past the list's end an entry repeats its last one and counts 0.
const int kGroup = 4;

// The area-weighted unit normal at p: the faces' cross products summed (+Z where they give no
// direction), scaled before its length is taken, since a huge normal's squared length overflows.
vec3 vertexNormal(vec3 p, ivec4 range) {
  vec3 n = vec3(0.0);
  for (int k = 0; k < range.w; k += kGroup) {
    ivec2 corners[kGroup];
    for (int j = 0; j < kGroup; ++j) corners[j] = texelFetch(u_faces, texelOf(range.z + min(k + j, range.w - 1)), 0).xy;
    for (int j = 0; j < kGroup; ++j) {
      vec3 c = cross(positionOf(corners[j].x) - p, positionOf(corners[j].y) - p);
      if (k + j < range.w && !any(isnan(c)) && !any(isinf(c))) n += c;
    }
  }
  float largest = max(max(abs(n.x), abs(n.y)), abs(n.z));
  return largest > 0.0 && !isinf(largest) ? normalize(n / largest) : vec3(0.0, 0.0, 1.0);
}

// Half the cotangent of the angle at o in the triangle (o, a, b); 0 where the corner has no angle
// to speak of (a zero-area triangle), as on the CPU.
float halfCotangent(vec3 o, vec3 a, vec3 b) {
  vec3 e1 = a - o, e2 = b - o;
  float area2 = length(cross(e1, e2));
  float scale = length(e1) * length(e2);
  if (!(area2 > 1e-12 * scale) || isinf(area2)) return 0.0;
  return 0.5 * dot(e1, e2) / area2;
}

float edgeWeight(vec3 p, vec3 q, ivec3 entry) {
#ifdef COTANGENT
  float w = 0.0;
  if (entry.y >= 0) w += halfCotangent(positionOf(entry.y), p, q);
  if (entry.z >= 0) w += halfCotangent(positionOf(entry.z), p, q);
#ifdef CLAMP_NEGATIVE
  w = max(w, 0.0);
#endif
  return w;
#else
  return 1.0;
#endif
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int v = (texel.y << 10) + texel.x;
  vec4 here = texelFetch(u_positions, texel, 0);
  if (v >= u_vertexCount) {  // padding: no vertex, no energy
    o_position = vec4(here.xyz, 0.0);
    return;
  }
  ivec4 range = texelFetch(u_ranges, texel, 0);
  vec3 sum = vec3(0.0), uniformSum = vec3(0.0);
  float weights = 0.0, magnitude = 0.0;
  for (int k = 0; k < range.y; k += kGroup) {
    ivec3 entries[kGroup];
    for (int j = 0; j < kGroup; ++j) entries[j] = texelFetch(u_ring, texelOf(range.x + min(k + j, range.y - 1)), 0).xyz;
    for (int j = 0; j < kGroup; ++j) {
      float counts = k + j < range.y ? 1.0 : 0.0;
      vec3 q = positionOf(entries[j].x);
      float w = counts * edgeWeight(here.xyz, q, entries[j]);
      sum += w * q;
      uniformSum += counts * q;
      weights += w;
      magnitude += abs(w);
    }
  }
  float energy = 0.0;
  vec3 next = here.xyz;
  if (range.y > 0) {  // an isolated vertex stays where it is
    // Every weight ~0 (a vertex amid slivers): no direction to move in, so uniform weights.
    vec3 mean = abs(weights) > 1e-9 * max(magnitude, 1e-30) ? sum / weights : uniformSum / float(range.y);
    next = laplacianStep(here.xyz, mean, vertexNormal(here.xyz, range), u_lambda, energy);
  }
  o_position = vec4(next, energy);
}
