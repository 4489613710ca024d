// Blinn-Phong / Phong reflection from point lights with inverse-square falloff.
// GAMES101 lecture 7; Blinn, "Models of light reflection for computer synthesized pictures", 1977.
//
//   L = ka*Ia + sum_k  (I_k / r_k^2) * ( kd * max(0, N.L_k) + ks * max(0, N.H_k)^p )    (Blinn-Phong)
//   Phong's specular uses max(0, R.V)^p with R = reflect(-L, N): for the same highlight size,
//   Blinn-Phong needs an exponent about 4x larger.
//
// The same function runs per face (flat), per vertex (Gouraud) or per fragment (Phong): the
// shading *frequency* is where it is called, not what it computes.

#ifndef NUM_LIGHTS
#define NUM_LIGHTS 1
#endif
#define MAX_LIGHTS 4

uniform vec3 u_lightPos[MAX_LIGHTS];    // world space
uniform vec3 u_lightPower[MAX_LIGHTS];  // radiant intensity x colour; divided by r^2
uniform vec3 u_ambient;                 // ambient light Ia
uniform float u_ka;
uniform float u_kd;
uniform float u_ks;
uniform float u_shininess;
uniform float u_minDistance2;           // r^2 never falls below this (a thousandth of the scene's radius, squared)

// normalize() of a zero vector is NaN; a degenerate triangle or a light exactly at the point
// would poison the frame. Fall back to a given direction instead.
vec3 safeNormalize(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1e-30 ? v * inversesqrt(len2) : fallback;
}

#include "common/specular.glsl"  // specularFactor()

struct Reflected {
  vec3 diffuse;   // to be multiplied by the surface albedo
  vec3 specular;  // white highlight
};

Reflected reflectLights(vec3 position, vec3 normal, vec3 eye) {
  vec3 N = safeNormalize(normal, vec3(0.0, 1.0, 0.0));
  vec3 V = safeNormalize(eye - position, N);
  Reflected r;
  r.diffuse = u_ka * u_ambient;
  r.specular = vec3(0.0);
  for (int k = 0; k < NUM_LIGHTS; ++k) {
    vec3 toLight = u_lightPos[k] - position;
    // Clamp r^2 so a light touching the surface stays finite (it would be infinite in theory); the
    // floor scales with the scene, so a scene a millimetre across is lit like one a metre across.
    float r2 = max(dot(toLight, toLight), u_minDistance2);
    vec3 L = toLight * inversesqrt(r2);
    vec3 E = u_lightPower[k] / r2;
    float NdotL = dot(N, L);
    if (NdotL <= 0.0) continue;  // light behind the surface: no diffuse, no highlight
    r.diffuse += u_kd * NdotL * E;
    r.specular += u_ks * pow(specularFactor(N, L, V), u_shininess) * E;
  }
  return r;
}
