// How varyings are interpolated across a triangle.
//   default         perspective-correct: attributes are interpolated as a/w and 1/w, then divided
//   AFFINE_UV       linear in screen space, as early PlayStation-era hardware did: straight checker
//                   lines bend on large triangles seen at an angle
//   UV_BY_HAND      perspective-correct, written out (shading/perspective_correct.glsl, the
//                   shading/perspective-correct exercise): the rasteriser interpolates what
//                   screenLinearUV() hands it linearly in screen space, perspectiveUV() recovers uv
//   flat lighting   one value per triangle (the provoking vertex's), no interpolation at all.
//
// Screen-linear varyings travel as `noperspective` where GLSL has it. GLSL ES 3.00 (WebGL2) has
// not: there a value v travels as (v w, w) with the default interpolation, and the quotient of the
// two is sum(b_i v_i w_i / w_i) / sum(b_i w_i / w_i) = sum(b_i v_i), with b_i the pixel's screen
// barycentrics: v, linear in screen space.
#if defined(AFFINE_UV) || defined(UV_BY_HAND)
#define SCREEN_LINEAR_UV 1
#ifdef SHADELAB_ES
#define SCREEN_LINEAR vec4
vec4 toScreenLinear(vec3 v, vec4 clip) { return vec4(v * clip.w, clip.w); }
vec3 fromScreenLinear(vec4 s) { return s.xyz / s.w; }
#else
#define SCREEN_LINEAR noperspective vec3
vec3 toScreenLinear(vec3 v, vec4 clip) { return v; }
vec3 fromScreenLinear(vec3 s) { return s; }
#endif
#endif
#ifdef UV_BY_HAND
#include "shading/perspective_correct.glsl"
#endif

#ifdef MODE_FLAT
#define LIGHT_INTERP flat
#else
#define LIGHT_INTERP
#endif
