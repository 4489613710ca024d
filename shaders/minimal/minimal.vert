#version 330 core
// Minimal lab, vertex stage: the position to clip space, the normal to world space.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_viewProj;
uniform mat3 u_normalMatrix;  // inverse transpose of the model matrix's upper 3x3: normals stay normal

out vec3 v_normal;

void main() {
  v_normal = u_normalMatrix * a_normal;
  gl_Position = u_viewProj * u_model * vec4(a_position, 1.0);
}
