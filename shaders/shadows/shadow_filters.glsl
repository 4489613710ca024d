// Shadow-map lookups for 2D maps (directional, spot) and cube maps (point lights), and the filters
// built on them. Each function takes the light's type as an int literal; after inlining the
// compiler keeps only that type's branch.
//
// Depth is compared *linearly* (distance along the light's axis, or from a point light), so bias
// and penumbra sizes are world lengths, whatever the projection stored. Bias is set in texels:
//   bias = max(k * (1 - N.L), b) * texelWorld        (slope-scaled, with b the constant floor)
//   P'   = P + N * normalOffset * texelWorld          (normal-offset bias moves the lookup point)
// RECEIVER_PLANE: a filter tap at an offset compares against the receiver's own plane *at that
// tap* (the tap's light ray intersected with the surface's plane), not the centre depth, so wide
// kernels on sloped receivers need no extra bias (Isidoro, "Shadow mapping: GPU-based tips and
// techniques", GDC 2006, does this with screen-space derivatives; the ray-plane form is exact).
// PCSS: Fernando, "Percentage-Closer Soft Shadows", SIGGRAPH 2005 sketch.
// Filtered maps store moments of depth instead and are blurred and mipmapped like any texture:
// VSM (Donnelly and Lauritzen 2006), ESM (Annen et al. 2008), EVSM (Lauritzen and McCool 2008).
//
// 2D maps are array textures: one layer per cascade (one layer when there are none); the layer
// travels in ShadowLight.layer.

#define LIGHT_DIRECTIONAL 0
#define LIGHT_SPOT 1
#define LIGHT_POINT 2

struct ShadowLight {
  mat4 viewProj;      // world -> light clip space (2D maps)
  vec3 position;
  vec3 axis;          // unit, from the light into the scene (directional, spot)
  vec3 right;         // world directions of the map's +u and +v (directional, spot)
  vec3 up;
  float nearPlane;
  float farPlane;
  float halfWidth;    // map plane half width: ortho half extent, or tan(half fov) (1 for cube faces)
  float mapSize;      // texels across
  float radius;       // area light: world radius (directional: tangent of the angular radius)
  float layer;        // 2D maps: the array layer (the cascade)
};

uniform float u_bias;          // texels
uniform float u_slopeBias;     // texels
uniform float u_normalOffset;  // texels
uniform float u_filterRadius;  // texels (Poisson PCF)
// Unit-disk samples, one well-spread set per count (never a prefix of a bigger one): the filter's
// taps (Poisson, PCSS) and the PCSS blocker search's.
uniform vec2 u_filterDisk[64];
uniform vec2 u_blockerDisk[64];

// What the filters need of the surface, taken in uniform control flow (derivatives are undefined
// inside a branch that differs between neighbouring pixels, as a cascade choice does).
struct ShadowSurface {
  vec3 P;       // world position
  vec3 N;       // shading normal, facing the viewer
  vec3 plane;   // the triangle's own normal, on N's side
  vec3 dPdx;    // screen derivatives of P
  vec3 dPdy;
};

ShadowSurface shadowSurface(vec3 P, vec3 N) {
  ShadowSurface s;
  s.P = P;
  s.N = N;
  s.dPdx = dFdx(P);
  s.dPdy = dFdy(P);
  vec3 geometric = cross(s.dPdx, s.dPdy);  // N may be interpolated; this is the triangle's plane
  s.plane = dot(geometric, geometric) > 0.0 ? normalize(geometric) : N;
  if (dot(s.plane, N) < 0.0) s.plane = -s.plane;
  return s;
}

struct ShadowQuery {
  vec3 point;      // the (normal-offset) receiver point
  vec3 plane;      // its geometric normal: the receiver plane for RECEIVER_PLANE
  vec2 tanCentre;  // spot: the centre tap's direction as tangents along right/up
  vec3 base;       // 2D: (uv, 0); cube: direction from the light
  vec3 tangent;    // cube: offset axes in the plane at unit distance
  vec3 bitangent;
  float depth;     // receiver's linear depth
  float bias;      // world units
  float texel;     // one texel in offset units (uv, or tangent at unit distance)
  float texelWorld;
  vec2 planeSlope; // directional RECEIVER_PLANE: the receiver plane's depth change per texel of offset
  bool beyondFar;
};

struct ShadowDebug {
  float heat;        // (receiver - occluder) in units of the bias, at the centre tap (1: acne begins)
  float gap;         // (receiver - occluder) in texels: large = shadowed by something else
  float blocker;     // PCSS average blocker depth, 0..1 over near..far (-1: none found)
  float penumbra;    // PCSS filter radius in texels
};

float lightDepth(int type, ShadowLight L, vec3 P) {
  return type == LIGHT_POINT ? length(P - L.position) : dot(P - L.position, L.axis);
}

float storedToLinear(int type, ShadowLight L, float z) {
  if (type == LIGHT_DIRECTIONAL) return mix(L.nearPlane, L.farPlane, z);
  if (type == LIGHT_SPOT) return L.nearPlane * L.farPlane / max(L.farPlane - z * (L.farPlane - L.nearPlane), 1e-30);
  return z * L.farPlane;
}

float linearToStored(int type, ShadowLight L, float d) {
  if (type == LIGHT_DIRECTIONAL) return (d - L.nearPlane) / (L.farPlane - L.nearPlane);
  if (type == LIGHT_SPOT) return (1.0 / L.nearPlane - 1.0 / max(d, 1e-30)) / (1.0 / L.nearPlane - 1.0 / L.farPlane);
  return d / L.farPlane;
}

// World size of a texel at linear depth d.
float texelWorldAt(int type, ShadowLight L, float d) {
  float span = 2.0 * L.halfWidth / L.mapSize;
  return type == LIGHT_DIRECTIONAL ? span : span * max(d, L.nearPlane);
}

vec3 toLightDir(int type, ShadowLight L, vec3 P) {
  return type == LIGHT_DIRECTIONAL ? -L.axis : normalize(L.position - P);
}

ShadowQuery makeQuery(int type, ShadowLight L, ShadowSurface s) {
  ShadowQuery q;
  vec3 P = s.P, N = s.N;
  float NdotL = clamp(dot(N, toLightDir(type, L, P)), 0.0, 1.0);
  q.texelWorld = texelWorldAt(type, L, lightDepth(type, L, P));
  vec3 Pn = P + N * (u_normalOffset * q.texelWorld);
  q.point = Pn;
  q.plane = s.plane;
  q.depth = lightDepth(type, L, Pn);
  q.bias = max(u_slopeBias * (1.0 - NdotL), u_bias) * q.texelWorld;
  q.beyondFar = q.depth > L.farPlane;
  if (type == LIGHT_POINT) {
    q.base = Pn - L.position;
    float len = length(q.base);
    q.base = len > 0.0 ? q.base / len : vec3(0.0, -1.0, 0.0);
    vec3 helper = abs(q.base.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    q.tangent = normalize(cross(helper, q.base));
    q.bitangent = cross(q.base, q.tangent);
    q.texel = 2.0 / L.mapSize;
  } else {
    vec4 clip = L.viewProj * vec4(Pn, 1.0);
    float w = abs(clip.w) > 1e-30 ? clip.w : 1e-30;
    // A point beside a spot light's eye (w near 0) projects towards infinity: held three map widths
    // out, where every lookup is outside the map as before, but finite (fract() of infinity is NaN).
    vec2 ndc = clamp(clip.xy / w, vec2(-3.0), vec2(3.0));
    q.base = vec3(ndc * 0.5 + 0.5, L.layer);
    q.tanCentre = ndc * L.halfWidth;
    q.beyondFar = q.beyondFar || clip.w <= 0.0;
    q.texel = 1.0 / L.mapSize;
    q.tangent = q.bitangent = vec3(0.0);
  }
  // Along a directional light's parallel rays the plane's depth is linear in the offset: one
  // gradient here instead of a ray-plane intersection per tap (receiverDepth). Zero where the
  // plane contains the light direction (no intersection).
  float denom = dot(L.axis, q.plane);
  q.planeSlope = abs(denom) < 1e-4 ? vec2(0.0) : -vec2(dot(L.right, q.plane), dot(L.up, q.plane)) * (q.texelWorld / denom);
  return q;
}

float tapLinear(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q, vec2 offsetTexels) {
  if (type == LIGHT_POINT) {
    vec3 dir = q.base + (q.tangent * offsetTexels.x + q.bitangent * offsetTexels.y) * q.texel;
    return storedToLinear(type, L, textureLod(cube, dir, 0.0).r);
  }
  return storedToLinear(type, L, textureLod(map, vec3(q.base.xy + offsetTexels * q.texel, q.base.z), 0.0).r);
}

// The receiver's depth where the tap's light ray meets the receiver plane (or the centre depth).
float receiverDepth(int type, ShadowLight L, ShadowQuery q, vec2 o) {
#ifdef RECEIVER_PLANE
  if (o == vec2(0.0)) return q.depth;
  float d;
  vec3 toP = q.point - L.position;
  if (type == LIGHT_DIRECTIONAL) {
    d = q.depth + dot(o, q.planeSlope);
  } else {
    vec3 dir = type == LIGHT_POINT ? q.base + (q.tangent * o.x + q.bitangent * o.y) * q.texel
                                   : L.axis + L.right * (q.tanCentre.x + o.x * q.texel * 2.0 * L.halfWidth) +
                                         L.up * (q.tanCentre.y + o.y * q.texel * 2.0 * L.halfWidth);
    float denom = dot(dir, q.plane);
    if (abs(denom) < 1e-4 * length(dir)) return q.depth;
    float t = dot(toP, q.plane) / denom;  // along dir (spot: dir has unit length along the axis)
    d = type == LIGHT_POINT ? t * length(dir) : t;
  }
  // Near-grazing planes extrapolate wildly: keep the change within a few texels per texel of offset.
  float limit = (length(o) + 1.0) * 4.0 * q.texelWorld;
  return clamp(d, q.depth - limit, q.depth + limit);
#else
  return q.depth;
#endif
}

float tapCompare(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q, vec2 offsetTexels) {
  return receiverDepth(type, L, q, offsetTexels) - q.bias > tapLinear(type, L, map, cube, q, offsetTexels) ? 0.0 : 1.0;
}

// Interleaved gradient noise (Jimenez 2014): a per-pixel value in [0, 1) with no visible pattern;
// as a rotation it turns Poisson banding into fine noise.
float pixelNoise() { return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715)))); }

float pixelAngle() { return 6.2831853 * pixelNoise(); }

vec2 rotated(vec2 v, float a) {
  float c = cos(a), s = sin(a);
  return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

// The filters an exercise asks for, each in its own file (a student's copy replaces just that one).
#if defined(FILTER_PCF)
#include "shadows/pcf.glsl"
#endif
#if defined(FILTER_PCSS)
#include "shadows/pcss_blocker.glsl"
#include "shadows/pcss_penumbra.glsl"
#endif
// The hard test written whole from the light's matrices, its guards included; with the far fix
// off the lab shows what the guard prevents through tapCompare instead.
#if defined(FILTER_HARD) && defined(FAR_FIX)
#define HARD_LOOKUP 1
#include "shadows/shadow_lookup.glsl"
#include "shadows/cube_lookup.glsl"
#endif

#if defined(FILTER_VSM) || defined(FILTER_ESM) || defined(FILTER_EVSM)
#define FILTER_MOMENTS 1
#endif

// Filtered maps. Depth is stored as t = (d - near) / (far - near) in [0, 1], linear along the
// light's axis, so the warps below never see more than exp(c).
uniform float u_minVariance;   // VSM/EVSM: floor on the variance (in t^2)
uniform float u_bleed;         // VSM: light-bleeding reduction, p -> (p - a) / (1 - a)
uniform float u_esmExponent;   // ESM: c in exp(c t)
uniform vec2 u_evsmExponents;  // EVSM: positive and negative warp exponents

float momentDepth(ShadowLight L, float d) {
  return clamp((d - L.nearPlane) / max(L.farPlane - L.nearPlane, 1e-30), 0.0, 1.0);
}

// What the depth pass stores for depth t (moments.frag), and what the filters compare against.
vec4 warpDepth(float t) {
#if defined(FILTER_ESM)
  return vec4(exp(u_esmExponent * t), 0.0, 0.0, 0.0);
#elif defined(FILTER_EVSM)
  float p = exp(u_evsmExponents.x * t), n = -exp(-u_evsmExponents.y * t);
  return vec4(p, p * p, n, n * n);
#else
  return vec4(t, t * t, 0.0, 0.0);
#endif
}

// Chebyshev's one-tailed bound: an upper bound on the lit fraction for receiver depth t.
float chebyshev(vec2 m, float t, float minVariance) {
  if (t <= m.x) return 1.0;
  float variance = max(m.y - m.x * m.x, minVariance);
  float d = t - m.x;
  return variance / (variance + d * d);
}

float momentVisibility(int type, ShadowLight L, sampler2DArray moments, ShadowSurface s, out ShadowDebug dbg) {
  ShadowQuery q = makeQuery(type, L, s);
  dbg.heat = 0.0;
  dbg.gap = 0.0;
  dbg.blocker = -1.0;
  dbg.penumbra = 0.0;
#ifdef FAR_FIX
  if (q.beyondFar) return 1.0;
#endif
  // The mip level from the surface's own screen derivatives, through the light's projection, one
  // per pixel: neighbouring pixels may read different cascades' maps (or take a branch others do
  // not), where a level chosen per 2x2 quad (textureGrad on llvmpipe) reads the wrong one.
  vec4 cx = L.viewProj * vec4(s.P + s.dPdx, 1.0), cy = L.viewProj * vec4(s.P + s.dPdy, 1.0);
  vec2 size = vec2(textureSize(moments, 0).xy);
  vec2 uvx = (cx.xy / max(abs(cx.w), 1e-30) * 0.5 + 0.5 - q.base.xy) * size;
  vec2 uvy = (cy.xy / max(abs(cy.w), 1e-30) * 0.5 + 0.5 - q.base.xy) * size;
  float lod = 0.5 * log2(max(max(dot(uvx, uvx), dot(uvy, uvy)), 1e-30));
  vec4 m = textureLod(moments, q.base, max(lod, 0.0));
  float t = momentDepth(L, q.depth - q.bias);
#if defined(FILTER_ESM)
  // exp(-c t) E[exp(c d)], in logs so neither factor overflows on its own.
  return clamp(exp(log(max(m.x, 1e-30)) - u_esmExponent * t), 0.0, 1.0);
#elif defined(FILTER_EVSM)
  vec4 w = warpDepth(t);
  // The variance floor scaled by each warp's slope at t (d/dt of exp(c t) is c exp(c t)).
  float dp = u_evsmExponents.x * w.x, dn = u_evsmExponents.y * w.z;
  float pos = chebyshev(m.xy, w.x, u_minVariance * dp * dp);
  float neg = chebyshev(m.zw, w.z, u_minVariance * dn * dn);
  return clamp(min(pos, neg), 0.0, 1.0);
#else
  float p = chebyshev(m.xy, t, u_minVariance);
  return clamp((p - u_bleed) / max(1.0 - u_bleed, 1e-6), 0.0, 1.0);
#endif
}

float visibility(int type, ShadowLight L, sampler2DArray map, samplerCube cube, sampler2DArrayShadow cmp,
                 samplerCubeShadow cmpCube, ShadowSurface s, out ShadowDebug dbg) {
  ShadowQuery q = makeQuery(type, L, s);
  float gap = q.depth - tapLinear(type, L, map, cube, q, vec2(0.0));
  dbg.heat = gap / max(q.bias, 1e-30);
  dbg.gap = gap / max(q.texelWorld, 1e-30);
  dbg.blocker = -1.0;
  dbg.penumbra = 0.0;
#if defined(FAR_FIX) && !defined(HARD_LOOKUP)  // the hard lookup guards the far plane itself
  if (q.beyondFar) return 1.0;  // nothing beyond the far plane was drawn into the map: call it lit
#endif
#if defined(FILTER_HW_PCF)
  // One tap; the sampler compares the four nearest texels and blends the results bilinearly.
  float ref = linearToStored(type, L, q.depth - q.bias);
  return type == LIGHT_POINT ? texture(cmpCube, vec4(q.base, ref)) : texture(cmp, vec4(q.base, ref));
#elif defined(FILTER_PCF)
  return pcf(type, L, map, cube, q);
#elif defined(FILTER_PCF_BILINEAR)
  // hardware-pcf written out: the four texels around the lookup, compared one by one and blended
  // by where the lookup falls between their centres.
  vec2 f = type == LIGHT_POINT ? vec2(0.5) : fract(q.base.xy * L.mapSize - 0.5);
  float t00 = tapCompare(type, L, map, cube, q, -f), t10 = tapCompare(type, L, map, cube, q, vec2(1.0, 0.0) - f);
  float t01 = tapCompare(type, L, map, cube, q, vec2(0.0, 1.0) - f), t11 = tapCompare(type, L, map, cube, q, vec2(1.0) - f);
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
#elif defined(FILTER_POISSON)
#ifdef ROTATE_SAMPLES
  float angle = pixelAngle();
#else
  float angle = 0.0;
#endif
  float lit = 0.0;
  for (int k = 0; k < POISSON_COUNT; ++k)
    lit += tapCompare(type, L, map, cube, q, rotated(u_filterDisk[k], angle) * u_filterRadius);
  return lit / float(POISSON_COUNT);
#elif defined(FILTER_PCSS)
  // Sizes on the map plane: world units for an orthographic map, tangents for a perspective one.
  float toTexels = L.mapSize / (2.0 * L.halfWidth);
  float n = L.nearPlane, dR = q.depth;
  // Blockers between depth zMin and the receiver can shade it; at depth z they lie within
  // R (dR - z) / (dR z) (tangent units) of the receiver's direction. Searching from the near plane
  // itself explodes when near is tiny (point lights), so blockers closer than a fifth of the
  // receiver's depth are not looked for.
  float zMin = max(n, 0.2 * dR);
  float search = type == LIGHT_DIRECTIONAL ? L.radius * max(dR - n, 0.0)
                                           : L.radius * max(dR - zMin, 0.0) / (dR * zMin);
  float searchTexels = search * toTexels;
  float angle = pixelAngle();
  // 1. Blocker search (shadows/pcss_blocker.glsl): the average depth of what lies between the
  // receiver and the light; none found, the receiver is lit.
  float blockers = averageBlockerDepth(type, L, map, cube, q, searchTexels, angle);
  if (blockers < 0.0) return 1.0;
  float dB = max(blockers, 1e-30);  // > 0 by construction; guarded for the division below
  dbg.blocker = clamp((dB - n) / (L.farPlane - n), 0.0, 1.0);
  // 2. Penumbra width by similar triangles (shadows/pcss_penumbra.glsl), as a filter size in texels.
  float filterTexels = penumbraTexels(type, L, dR, dB, toTexels);
  dbg.penumbra = filterTexels;
  // 3. PCF over that width.
  float lit = 0.0;
  for (int k = 0; k < PCSS_COUNT; ++k)
    lit += tapCompare(type, L, map, cube, q, rotated(u_filterDisk[k], angle) * filterTexels);
  return lit / float(PCSS_COUNT);
#elif defined(HARD_LOOKUP)
  // shadows/shadow_lookup.glsl and cube_lookup.glsl: the receiver point and bias are all they take.
  return type == LIGHT_POINT ? cubeShadowLookup(L, cube, q.point, q.bias) : shadowLookup(type, L, map, q.point, q.bias);
#else
  return tapCompare(type, L, map, cube, q, vec2(0.0));
#endif
}
