#version 410 core
// Test shader: the scalar attribute in red, 1 in green.
in float v_scalar;
out vec4 o_color;
void main() { o_color = vec4(v_scalar, 1.0, 0.0, 1.0); }
