#version 330 core
// Shadows lab, depth pass. A 2D map (directional, spot) projects straight into the light's clip
// space; a cube map (point light) passes world positions on to depth_cube.geom, which draws each
// triangle into all six faces in one pass.
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_lightViewProj;

void main() {
#ifdef CUBE_MAP
  gl_Position = u_model * vec4(a_position, 1.0);
#else
  gl_Position = u_lightViewProj * u_model * vec4(a_position, 1.0);
#endif
}
