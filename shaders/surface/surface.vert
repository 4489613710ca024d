#version 410 core
// Surface-detail lab, vertex stage. Passes the surface on; with DISPLACE_VERTEX it moves each
// vertex along its normal by the height field: p' = p + n s (h(uv) - base), base 1 when the
// surface sits at the top of the field (parallax's convention), 0 when at its bottom (the
// GAMES101 form p + n s h). How fine that is depends on the mesh: the lab subdivides it.
// With TESSELLATED the displacement waits for the evaluation stage (surface.tese).
// VERTEX_NORMALS gives the vertex the displaced surface's normal as well (displaced_normals =
// per-vertex), interpolated across each triangle like any mesh normal.
// Read next: surface.tese, surface.frag.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;         // the frame the technique uses
layout(location = 4) in float a_uvScaleU;       // world length of one unit of u here
layout(location = 5) in float a_uvScaleV;       // ... and of v
layout(location = 6) in vec4 a_compareTangent;  // the frame the tangent-angle view compares with

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;
#ifdef DISPLACE_VERTEX
uniform sampler2D u_heightMap;
uniform float u_heightScale;
uniform float u_heightBase;
uniform vec2 u_heightTexel;  // 1 / the height map's size
#include "surface/displace.glsl"  // displacedPosition(), displacedNormal()
#endif

out Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} vout;

void main() {
  vec3 p = a_position;
  vec3 n = a_normal;
#ifdef DISPLACE_VERTEX
  p = displacedPosition(p, n, a_uv);
#ifdef VERTEX_NORMALS
  n = displacedNormal(n, a_tangent, a_uv, vec2(a_uvScaleU, a_uvScaleV), u_heightTexel);
#endif
#endif
  vec4 world = u_model * vec4(p, 1.0);
  vout.world = world.xyz;
  vout.normal = u_normalMatrix * n;
  vout.uv = a_uv;
  vout.tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w);
  vout.compareTangent = vec4(mat3(u_model) * a_compareTangent.xyz, a_compareTangent.w);
  // The model matrix scales world lengths too (a uniform scale in these scenes).
  float s = length(mat3(u_model)[0]);
  vout.uvScale = vec2(a_uvScaleU, a_uvScaleV) * s;
#ifdef TESSELLATED
  vout.world = p;  // object space: the evaluation stage displaces, then transforms
  vout.normal = n;
  gl_Position = vec4(p, 1.0);
#else
  gl_Position = u_viewProj * world;
#endif
}
