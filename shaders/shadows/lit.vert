#version 330 core
// Shadows lab, camera pass: world position and normal for the shadow lookups in lit.frag.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;

out vec3 v_worldPos;
out vec3 v_normal;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_worldPos = world.xyz;
  v_normal = u_normalMatrix * a_normal;
  gl_Position = u_viewProj * world;
}
