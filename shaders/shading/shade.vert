#version 330 core
// Shading lab, vertex stage. In Gouraud mode the lighting is evaluated here, once per vertex,
// and the rasteriser interpolates colours; otherwise positions and normals are passed on.
// Flat mode lights each face in flat.geom, or here where there is no geometry stage (WebGL2): the
// mesh is then unwelded (FLAT_UNWELDED), every corner carrying its face's normal and centroid.
// Read next: shade.frag (Phong: per fragment), flat.geom (flat: per face).
#include "common/lighting.glsl"
#include "shading/interpolation.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
#ifdef FLAT_UNWELDED
layout(location = 6) in vec4 a_faceCentre;  // the face's centroid; a_normal is the face's normal
#endif

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;  // inverse transpose of the model matrix's upper 3x3
uniform vec3 u_eye;

#if defined(MODE_FLAT) && !defined(FLAT_UNWELDED)
out Vertex {  // to flat.geom, which lights each face
#else
out Surface {  // straight to shade.frag
#endif
  vec3 worldPos;
  vec3 normal;
  vec2 uv;
#ifdef SCREEN_LINEAR_UV
  SCREEN_LINEAR uvLinear;  // interpolation.glsl
#endif
#ifdef MODE_GOURAUD
  vec3 diffuse;       // lit on the normal's side ...
  vec3 specular;
  vec3 diffuseBack;   // ... and on the other: the fragment stage picks the side the eye sees
  vec3 specularBack;
#elif defined(FLAT_UNWELDED)
  LIGHT_INTERP vec3 diffuse;  // the face's, alike at its three corners
  LIGHT_INTERP vec3 specular;
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
#elif defined(FLAT_UNWELDED)
  // As flat.geom: lit once, at the centroid, on the side the eye sees.
  vec3 centre = (u_model * vec4(a_faceCentre.xyz, 1.0)).xyz;
  vec3 N = safeNormalize(vout.normal, vec3(0.0, 1.0, 0.0));
  if (dot(N, u_eye - centre) < 0.0) N = -N;
  Reflected lit = reflectLights(centre, N, u_eye);
  vout.normal = N;
  vout.diffuse = lit.diffuse;
  vout.specular = lit.specular;
#endif
  gl_Position = u_viewProj * world;
#if defined(UV_BY_HAND)
  vout.uvLinear = toScreenLinear(screenLinearUV(a_uv, gl_Position), gl_Position);
#elif defined(AFFINE_UV)
  vout.uvLinear = toScreenLinear(vec3(a_uv, 0.0), gl_Position);
#endif
}
