#version 330 core
// The light's frustum as lines: corners come from the inverse of its view-projection.
layout(location = 0) in vec3 a_position;  // in light NDC, [-1, 1]^3
uniform mat4 u_viewProj;
uniform mat4 u_lightInverse;
void main() {
  vec4 world = u_lightInverse * vec4(a_position, 1.0);
  gl_Position = u_viewProj * vec4(world.xyz / world.w, 1.0);
}
