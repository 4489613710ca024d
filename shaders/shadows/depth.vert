#version 330 core
// Shadows lab, depth pass. A 2D map (directional, spot) projects straight into the light's clip
// space; a cube map (point light) passes world positions on to depth_cube.geom, which draws each
// triangle into all six faces in one pass. CUBE_FACE draws one face per pass instead (six passes;
// the lab measures both: cube_passes = one | six). MOMENTS passes world positions on to
// moments.frag, which stores the moments of depth a filtered map (VSM, ESM, EVSM) is made of.
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_lightViewProj;
#if defined(CUBE_FACE) || defined(MOMENTS)
out vec3 g_worldPos;
#endif

void main() {
#ifdef CUBE_MAP
  gl_Position = u_model * vec4(a_position, 1.0);
#elif defined(CUBE_FACE)
  vec4 world = u_model * vec4(a_position, 1.0);
  g_worldPos = world.xyz;
  gl_Position = u_lightViewProj * world;
#elif defined(MOMENTS)
  vec4 world = u_model * vec4(a_position, 1.0);
  g_worldPos = world.xyz;
  gl_Position = u_lightViewProj * world;
#else
  gl_Position = u_lightViewProj * u_model * vec4(a_position, 1.0);
#endif
}
