#version 330 core
// Shadows lab, depth pass of a filtered map: besides depth, store the moments of the surface's
// normalised linear depth t (warpDepth: t and t^2 for VSM, exp(c t) for ESM, both exponential
// warps and their squares for EVSM). Unlike depth, moments can be blurred and mipmapped: the
// average of t and t^2 over a region is still their mean and second moment there.
// Read next: momentVisibility in shadow_filters.glsl.
#include "shadows/shadow_filters.glsl"

in vec3 g_worldPos;
uniform vec3 u_lightPos;
uniform vec3 u_lightAxis;  // unit, into the scene
uniform float u_near;
uniform float u_far;
out vec4 o_moments;

void main() {
  float d = dot(g_worldPos - u_lightPos, u_lightAxis);
  o_moments = warpDepth(clamp((d - u_near) / max(u_far - u_near, 1e-30), 0.0, 1.0));
}
