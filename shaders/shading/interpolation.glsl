// How varyings are interpolated across a triangle.
//   default         perspective-correct: attributes are interpolated as a/w and 1/w, then divided
//   AFFINE_UV       `noperspective`: linear in screen space, as early PlayStation-era hardware did;
//                   straight checker lines bend on large triangles seen at an angle.
//   flat lighting   one value per triangle (the provoking vertex's), no interpolation at all.
#if defined(AFFINE_UV) && !defined(SHADELAB_ES)  // GLSL ES 3.00 has no noperspective
#define UV_INTERP noperspective
#else
#define UV_INTERP
#endif

#ifdef MODE_FLAT
#define LIGHT_INTERP flat
#else
#define LIGHT_INTERP
#endif
