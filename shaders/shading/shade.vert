#version 330 core
// Shading lab, vertex stage. In Gouraud mode the lighting is evaluated here, once per vertex,
// and the rasteriser interpolates colours; otherwise positions and normals are passed on.
// Read next: shade.frag (Phong: per fragment), flat.geom (flat: per face).
#include "common/lighting.glsl"
#include "shading/interpolation.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;  // inverse transpose of the model matrix's upper 3x3
uniform vec3 u_eye;

#ifdef MODE_FLAT
out Vertex {  // to flat.geom, which lights each face
#else
out Surface {  // straight to shade.frag
#endif
  vec3 worldPos;
  vec3 normal;
  UV_INTERP vec2 uv;
#ifdef MODE_GOURAUD
  vec3 diffuse;       // lit on the normal's side ...
  vec3 specular;
  vec3 diffuseBack;   // ... and on the other: the fragment stage picks the side the eye sees
  vec3 specularBack;
#endif
} vout;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  vout.worldPos = world.xyz;
  vout.normal = u_normalMatrix * a_normal;
  vout.uv = a_uv;
#ifdef MODE_GOURAUD
  Reflected lit = reflectLights(world.xyz, vout.normal, u_eye);
  vout.diffuse = lit.diffuse;
  vout.specular = lit.specular;
  Reflected back = reflectLights(world.xyz, -vout.normal, u_eye);
  vout.diffuseBack = back.diffuse;
  vout.specularBack = back.specular;
#endif
  gl_Position = u_viewProj * world;
}
