#version 330 core
// Minimal lab, fragment stage: Lambert's cosine law under one directional light, or the normal
// itself as a colour (VIEW_NORMALS). Edit it in your shader folder and the window reloads it.
#include "common/output.glsl"

in vec3 v_normal;
out vec4 o_color;

#ifndef VIEW_NORMALS
uniform vec3 u_toLight;  // unit vector towards the light
uniform vec3 u_albedo;   // the material's base colour, linear
#endif

void main() {
  vec3 n = normalize(v_normal);
#ifdef VIEW_NORMALS
  o_color = vec4(0.5 * n + 0.5, 1.0);  // data, not light: written as it is, not sRGB-encoded
#else
  float cosine = max(dot(n, u_toLight), 0.0);
  vec3 ambient = vec3(0.08);  // stands in for the light that is not modelled, so shadowed sides are not black
  o_color = encodeOutput(u_albedo * (ambient + cosine));
#endif
}
