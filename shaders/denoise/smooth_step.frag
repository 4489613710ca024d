#version 330 core
// Denoising on the GPU: one explicit step for every vertex, a fragment each (labs/denoise/gpu_smoother.h).
// Vertex v lives at texel (v % width, v / width) of every per-vertex texture. Its one-ring comes
// from a compressed-row layout: u_ranges gives where v's neighbours start and how many there are;
// u_ring gives each neighbour j and the vertices opposite the edge (v, j) (-1: none), whose angles
// make the cotangent weight. The weights follow laplacian.cpp's edgeWeights() rule for rule, so
// the CPU and the GPU smooth the same mesh the same way.
// Writes the new position in .xyz and this vertex's energy term, measured before the step, in .w.
#include "denoise/laplacian_step.glsl"

uniform sampler2D u_positions;  // .xyz, relative to the mesh's centre
uniform sampler2D u_normals;    // unit vertex normals of u_positions (vertex_normals.frag)
uniform isampler2D u_ranges;    // ring start, ring count, face start, face count
uniform isampler2D u_ring;      // neighbour, opposite vertex, the other opposite vertex
uniform int u_vertexCount;
uniform float u_lambda;
out vec4 o_position;

ivec2 texelOf(int index, int width) { return ivec2(index % width, index / width); }
vec3 positionOf(int v) { return texelFetch(u_positions, texelOf(v, textureSize(u_positions, 0).x), 0).xyz; }

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
  int v = texel.y * textureSize(u_positions, 0).x + texel.x;
  vec4 here = texelFetch(u_positions, texel, 0);
  if (v >= u_vertexCount) {  // padding: no vertex, no energy
    o_position = vec4(here.xyz, 0.0);
    return;
  }
  ivec4 range = texelFetch(u_ranges, texel, 0);
  int ringWidth = textureSize(u_ring, 0).x;
  vec3 sum = vec3(0.0), uniformSum = vec3(0.0);
  float weights = 0.0, magnitude = 0.0;
  for (int k = 0; k < range.y; ++k) {
    ivec3 entry = texelFetch(u_ring, texelOf(range.x + k, ringWidth), 0).xyz;
    vec3 q = positionOf(entry.x);
    float w = edgeWeight(here.xyz, q, entry);
    sum += w * q;
    uniformSum += q;
    weights += w;
    magnitude += abs(w);
  }
  float energy = 0.0;
  vec3 next = here.xyz;
  if (range.y > 0) {  // an isolated vertex stays where it is
    // Every weight ~0 (a vertex amid slivers): no direction to move in, so uniform weights.
    vec3 mean = abs(weights) > 1e-9 * max(magnitude, 1e-30) ? sum / weights : uniformSum / float(range.y);
    next = laplacianStep(here.xyz, mean, texelFetch(u_normals, texel, 0).xyz, u_lambda, energy);
  }
  o_position = vec4(next, energy);
}
