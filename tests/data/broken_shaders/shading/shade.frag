#version 330 core
// A student's shade.frag with a typo on line 6: every variant of the shading lab must
// report it at this file, line 6, and keep going.
out vec4 o_color;
void main() {
  o_color = vec4(undeclaredColor, 1.0);
}
