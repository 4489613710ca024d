#version 330 core
// Shading lab, fragment stage. Phong shading lights every fragment with the interpolated
// (renormalised) normal; flat and Gouraud only multiply the colour they were handed by the
// surface albedo. Try: raise shininess in Gouraud mode and watch the highlight vanish between
// vertices; switch to Phong and it comes back.
#include "common/lighting.glsl"
#include "common/output.glsl"
#include "shading/interpolation.glsl"

uniform vec3 u_eye;
uniform vec4 u_baseColor;
#ifdef BASE_COLOR_MAP
uniform sampler2D u_baseColorMap;  // sRGB texture: sampled values are already linear
#endif

in Surface {
  vec3 worldPos;
  vec3 normal;
  vec2 uv;
#ifdef SCREEN_LINEAR_UV
  SCREEN_LINEAR uvLinear;  // interpolation.glsl
#endif
#if defined(MODE_GOURAUD) || defined(MODE_FLAT)
  LIGHT_INTERP vec3 diffuse;
  LIGHT_INTERP vec3 specular;
#endif
#ifdef MODE_GOURAUD
  LIGHT_INTERP vec3 diffuseBack;
  LIGHT_INTERP vec3 specularBack;
#endif
} fin;

// Which side of the surface the eye sees, whatever the triangle's winding: the triangle's own
// plane (from screen derivatives) turned towards the eye, then the interpolated normal turned to
// agree with it. gl_FrontFacing would follow the winding, which mixed-winding files get wrong.
bool seenFromNormalSide(vec3 worldPos, vec3 normal) {
  vec3 face = cross(dFdx(worldPos), dFdy(worldPos));
  if (dot(face, face) == 0.0) return true;
  if (dot(face, u_eye - worldPos) < 0.0) face = -face;
  return dot(normal, face) >= 0.0;
}

out vec4 o_color;

void main() {
  vec3 albedo = u_baseColor.rgb;
#ifdef BASE_COLOR_MAP
#if defined(UV_BY_HAND)
  vec2 uv = perspectiveUV(fromScreenLinear(fin.uvLinear));
#elif defined(AFFINE_UV)
  vec2 uv = fromScreenLinear(fin.uvLinear).xy;
#else
  vec2 uv = fin.uv;
#endif
  albedo *= texture(u_baseColorMap, uv).rgb;
#endif
  bool front = seenFromNormalSide(fin.worldPos, fin.normal);
#if defined(MODE_FLAT)
  vec3 diffuse = fin.diffuse;  // flat.geom (or the unwelded vertex stage) lit the side the eye sees already
  vec3 specular = fin.specular;
#elif defined(MODE_GOURAUD)
  // Seen from behind (open meshes, the inside of a teapot), the other side's lighting.
  vec3 diffuse = front ? fin.diffuse : fin.diffuseBack;
  vec3 specular = front ? fin.specular : fin.specularBack;
#else
  // Seen from behind (open meshes, the inside of a teapot), light the side we see.
  vec3 N = front ? fin.normal : -fin.normal;
  Reflected lit = reflectLights(fin.worldPos, N, u_eye);
  vec3 diffuse = lit.diffuse;
  vec3 specular = lit.specular;
#endif
  o_color = encodeOutput(albedo * diffuse + specular);
}
