#version 330 core
// A shader that produces NaN at run time (sqrt of a negative number): `shadelab stress` must
// notice it in the float target and fail.
uniform float u_ka;
out vec4 o_color;
void main() {
  o_color = vec4(sqrt(-1.0 - u_ka), 0.0, 0.0, 1.0);
}
