#version 410 core
// Surface-detail lab, fragment stage: one normal per pixel, from whichever technique is compiled
// in, then Blinn-Phong under one directional light. The techniques:
//   (none)          the mesh's own normal: a flat wall
//   NORMAL_MAP      a tangent-space normal map: n = T x + B y + N z with (x, y, z) = 2c - 1
//   BUMP            a normal from the height field's slope (GAMES101 or consistent, height.glsl)
//   HEIGHT_NORMALS  displacement: the geometry moved already; the normal from the height field
//   PARALLAX, STEEP, POM   the texture lookups moved as if the surface had depth (height.glsl)
// and the mistakes on the way (WRONG_ADD_TO_NORMAL, WRONG_NO_RENORMALIZE, WRONG_NO_ORTHOGONALIZE,
// a normal map decoded as sRGB or with the other green convention: set by the lab, see its help).
// Read next: common/tangent_frame.glsl, height.glsl, tutorials/surface.md.
#include "common/output.glsl"
#include "common/tangent_frame.glsl"
// (The truth's self-shadowing marches the height field too, whatever its normals come from.)
#if defined(BUMP) || defined(HEIGHT_NORMALS) || defined(PARALLAX) || defined(STEEP) || defined(POM) || defined(VIEW_HEIGHT) || defined(TRUE_SHADOW)
#define USES_HEIGHT 1
#include "surface/height.glsl"
#endif

in Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} fin;

uniform vec3 u_eye;
uniform vec3 u_lightDir;        // towards the light, world space
uniform vec4 u_baseColor;
uniform sampler2D u_baseColorMap;
#ifdef NORMAL_MAP
uniform sampler2D u_normalMap;
uniform float u_normalStrength;  // scales the map's x and y
uniform float u_greenSign;       // +1 OpenGL (+Y along +v), -1 DirectX
#endif
#ifdef BUMP
uniform float u_kh, u_kn;
#endif
#ifdef VIEW_TANGENT_ANGLE
uniform float u_angleScale;  // degrees at full colour
#endif
#if defined(PARALLAX) || defined(STEEP) || defined(POM)
uniform int u_layers;  // depth slices to march (steep, POM) and the self-shadow ray's steps
#endif

out vec4 o_color;

// Which frame this fragment uses: the per-vertex one (TANGENTS_SCREEN undefined) or per-pixel.
mat3 frame(vec4 tangent, bool screen) {
#ifdef WRONG_NO_RENORMALIZE
  const bool renormalize = false;
#else
  const bool renormalize = true;
#endif
#ifdef WRONG_NO_ORTHOGONALIZE
  const bool orthogonalize = false;
#else
  const bool orthogonalize = true;
#endif
  vec3 n = gl_FrontFacing ? fin.normal : -fin.normal;  // open meshes: the side we see
  if (screen) return screenSpaceFrame(n, fin.world, fin.uv);
  return vertexFrame(n, gl_FrontFacing ? tangent : vec4(tangent.xyz, -tangent.w), orthogonalize, renormalize);
}

// Tangent-space normal -> world. The right way replaces the surface normal; the wrong way adds the
// perturbation to the old normal (n_old + TBN (2c - 1)), which tilts every pixel towards N twice.
vec3 toWorld(mat3 tbn, vec3 nTs) {
#ifdef WRONG_ADD_TO_NORMAL
  vec3 n = tbn[2] + tbn * nTs;
#else
  vec3 n = tbn * nTs;
#endif
#ifdef WRONG_NO_RENORMALIZE
  return n;
#else
  float len = length(n);
  return len > 1e-6 ? n / len : tbn[2];  // an all-zero texel (a float map can hold one) has no direction
#endif
}

#ifdef NORMAL_MAP
#include "surface/normal_map.glsl"  // normalFromMap()
#endif

void main() {
#ifdef USES_HEIGHT
  initHeightGradients(fin.uv);
#endif
#ifdef TANGENTS_SCREEN
  mat3 tbn = frame(fin.tangent, true);
#else
  mat3 tbn = frame(fin.tangent, false);
#endif
  vec3 V = normalize(u_eye - fin.world);
  vec2 uv = fin.uv;
  float shadow = 1.0;

#if defined(PARALLAX) || defined(STEEP) || defined(POM)
  readNearestLevel(true);  // the marches (height.glsl says why)
  vec3 viewTs = normalize(transpose(tbn) * V);
  float depth = 0.0;
#ifdef PARALLAX
  uv = parallaxOffset(uv, viewTs, fin.uvScale, depth);
#elif defined(POM)
  uv = parallaxMarch(uv, viewTs, fin.uvScale, u_layers, true, depth);
#else
  uv = parallaxMarch(uv, viewTs, fin.uvScale, u_layers, false, depth);
#endif
#ifdef SELF_SHADOW
  shadow = parallaxShadow(uv, depth, normalize(transpose(tbn) * u_lightDir), fin.uvScale, max(u_layers, 8));
#endif
  readNearestLevel(false);  // the normal at the pixel's own level
#endif
#ifdef TRUE_SHADOW
  shadow = heightFieldVisibility(uv, 1.0 - heightAt(uv), normalize(transpose(tbn) * u_lightDir), fin.uvScale);
#endif

  vec3 N = tbn[2];
#if defined(NORMAL_MAP)
  vec3 c = texture(u_normalMap, uv).rgb;
#if defined(WRONG_ADD_TO_NORMAL) || defined(WRONG_NO_RENORMALIZE)
  // The lab's wrong steps, shown on purpose: toWorld() takes them.
  N = toWorld(tbn, vec3((2.0 * c.xy - 1.0) * u_normalStrength * vec2(1.0, u_greenSign), 2.0 * c.z - 1.0));
#else
  N = normalFromMap(tbn, c);
#endif
#elif defined(BUMP)
#ifdef BUMP_GAMES101
  N = toWorld(tbn, bumpNormalGames101(uv, u_kh, u_kn));
#else
  N = toWorld(tbn, heightNormal(uv, fin.uvScale));
#endif
#elif defined(HEIGHT_NORMALS) || defined(PARALLAX) || defined(STEEP) || defined(POM)
  N = toWorld(tbn, heightNormal(uv, fin.uvScale));
#endif

#if defined(VIEW_NORMALS)
  o_color = vec4(N * 0.5 + 0.5, 1.0);  // world normal, 0.5 +- 0.5 per axis (the metrics decode it)
#elif defined(VIEW_TANGENT_ANGLE)
  // The angle between this fragment's tangent and the other source's: 0 slate, through pink-red at
  // half of u_angleScale, to yellow at u_angleScale.
#ifdef COMPARE_SCREEN
  vec3 other = frame(fin.compareTangent, true)[0];
#else
  vec3 other = frame(fin.compareTangent, false)[0];
#endif
  float angle = degrees(acos(clamp(dot(tbn[0], other), -1.0, 1.0)));
  float t = clamp(angle / u_angleScale, 0.0, 1.0);
  vec3 heat = mix(mix(vec3(0.33, 0.36, 0.45), vec3(0.85, 0.25, 0.35), smoothstep(0.0, 0.5, t)), vec3(1.0, 0.95, 0.5),
                  smoothstep(0.5, 1.0, t));
  heat *= 0.6 + 0.4 * max(dot(N, u_lightDir), 0.0);  // dimmed by the light so the shape still reads
  o_color = vec4(linearToSrgb(heat), 1.0);
#elif defined(VIEW_HEIGHT)
  o_color = vec4(vec3(heightAt(uv)), 1.0);
#elif defined(VIEW_UV)
  o_color = vec4(fract(uv), 0.0, 1.0);
#else
  vec3 albedo = u_baseColor.rgb * texture(u_baseColorMap, uv).rgb;
  float ndl = max(dot(N, u_lightDir), 0.0);
  vec3 H = normalize(u_lightDir + V);
  float spec = ndl > 0.0 ? pow(max(dot(N, H), 0.0), 48.0) : 0.0;
  vec3 lit = albedo * (0.12 + 0.88 * ndl * shadow) + vec3(0.25) * spec * shadow;
  o_color = encodeOutput(lit);
#endif
}
