#version 410 core
// Texture-filtering lab, vertex stage: nothing but the position and the texture coordinate.
// Everything this lab is about happens per fragment (filtering.frag, filter.glsl).
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_viewProj;

out vec2 v_uv;

void main() {
  v_uv = a_uv;
  gl_Position = u_viewProj * u_model * vec4(a_position, 1.0);
}
