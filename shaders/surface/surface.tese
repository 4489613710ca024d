#version 410 core
// Surface-detail lab, tessellation evaluation: every generated vertex interpolates its patch's
// attributes and is displaced as in surface.vert, p' = p + n s (h(uv) - base). The patch is the
// base mesh's triangle: no subdivision on the CPU, as fine as u_tessLevel asks.
layout(triangles, equal_spacing, ccw) in;

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;
uniform sampler2D u_heightMap;
uniform float u_heightScale;
uniform float u_heightBase;
#include "surface/displace.glsl"  // displacedPosition(); the normals come from the fragment stage

in Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} tein[];

out Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} teout;

#define LERP(field) (gl_TessCoord.x * tein[0].field + gl_TessCoord.y * tein[1].field + gl_TessCoord.z * tein[2].field)

void main() {
  vec3 p = LERP(world);  // object space (surface.vert with TESSELLATED)
  vec3 n = normalize(LERP(normal));
  vec2 uv = LERP(uv);
  p = displacedPosition(p, n, uv);
  vec4 world = u_model * vec4(p, 1.0);
  teout.world = world.xyz;
  teout.normal = u_normalMatrix * n;
  teout.uv = uv;
  vec4 t = LERP(tangent), c = LERP(compareTangent);  // already in world space (surface.vert)
  teout.tangent = vec4(t.xyz, tein[0].tangent.w);
  teout.compareTangent = vec4(c.xyz, tein[0].compareTangent.w);
  teout.uvScale = LERP(uvScale);
  gl_Position = u_viewProj * world;
}
