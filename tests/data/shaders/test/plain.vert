#version 410 core
// Test shader: positions straight to clip space; a per-vertex scalar rides along.
layout(location = 0) in vec3 a_position;
layout(location = 4) in float a_scalar;
out float v_scalar;
void main() {
  v_scalar = a_scalar;
  gl_Position = vec4(a_position, 1.0);
}
