#version 330 core
// Denoising lab, vertex stage: the three ways a result reaches the screen.
//   plain             the positions as they are (smoothed, noisy or clean, uploaded by the lab)
//   DISPLACE_MAP      the noisy mesh, each vertex moved along its normal by the offset the
//                     displacement map holds at its UV: p' = p + n (texel * scale + bias).
//                     Copies of a position on a UV seam read different texels; if those differ,
//                     the copies part and the mesh cracks.
//   DISPLACE_ATTRIBUTE the same offsets per vertex, as an attribute: copies that share a
//                     position share the offset (computed on the welded mesh), so nothing parts.
//   SMOOTHED_ON_GPU   the smoothed positions straight from the GPU smoother's texture, at the
//                     vertex's index there (labs/denoise/gpu_smoother.h): no read-back to draw
//                     them, while the job that measures them still runs.
// Read next: apply_map.glsl (the map's lookup), mesh.frag (flat shading and the heat views),
// labs/denoise/displacement_bake.h.
#ifdef DISPLACE_MAP
#include "denoise/apply_map.glsl"
#endif

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;    // the noisy surface's normal: the direction offsets move along
layout(location = 2) in vec2 a_uv;
#ifdef SMOOTHED_ON_GPU
layout(location = 4) in float a_vertex;   // the index of this vertex's texel in u_smoothed
uniform sampler2D u_smoothed;             // .xyz relative to u_centre, 1024 texels a row
uniform vec3 u_centre;
#else
layout(location = 4) in float a_offset;   // DISPLACE_ATTRIBUTE
#endif
layout(location = 5) in float a_heat;     // the view's scalar: error, offset or seam gap

uniform mat4 u_viewProj;
uniform float u_pointSize;  // pixels, where the mesh is drawn as points (the point a mesh collapsed to)

out vec3 v_world;
out float v_heat;

void main() {
  vec3 p = a_position;
#if defined(SMOOTHED_ON_GPU)
  int i = int(a_vertex);
  p = texelFetch(u_smoothed, ivec2(i & 1023, i >> 10), 0).xyz + u_centre;
#elif defined(DISPLACE_MAP)
  p = displacedByMap(p, a_normal, a_uv);
#elif defined(DISPLACE_ATTRIBUTE)
  p += a_normal * a_offset;
#endif
  v_world = p;
  v_heat = a_heat;
  gl_Position = u_viewProj * vec4(p, 1.0);
  gl_PointSize = u_pointSize;
}
