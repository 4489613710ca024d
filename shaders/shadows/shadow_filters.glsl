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
};

uniform float u_bias;          // texels
uniform float u_slopeBias;     // texels
uniform float u_normalOffset;  // texels
uniform float u_filterRadius;  // texels (Poisson PCF)
uniform vec2 u_poisson[64];    // unit-disk samples

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
  bool beyondFar;
};

struct ShadowDebug {
  float heat;        // (receiver - occluder - bias) in texels, at the centre tap
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

ShadowQuery makeQuery(int type, ShadowLight L, vec3 P, vec3 N) {
  ShadowQuery q;
  float NdotL = clamp(dot(N, toLightDir(type, L, P)), 0.0, 1.0);
  q.texelWorld = texelWorldAt(type, L, lightDepth(type, L, P));
  vec3 Pn = P + N * (u_normalOffset * q.texelWorld);
  q.point = Pn;
  vec3 geometric = cross(dFdx(P), dFdy(P));  // the triangle's plane; N may be interpolated
  q.plane = dot(geometric, geometric) > 0.0 ? normalize(geometric) : N;
  if (dot(q.plane, N) < 0.0) q.plane = -q.plane;
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
    q.base = vec3(clip.xy / w * 0.5 + 0.5, 0.0);
    q.tanCentre = (clip.xy / w) * L.halfWidth;
    q.beyondFar = q.beyondFar || clip.w <= 0.0;
    q.texel = 1.0 / L.mapSize;
    q.tangent = q.bitangent = vec3(0.0);
  }
  return q;
}

float tapLinear(int type, ShadowLight L, sampler2D map, samplerCube cube, ShadowQuery q, vec2 offsetTexels) {
  if (type == LIGHT_POINT) {
    vec3 dir = q.base + (q.tangent * offsetTexels.x + q.bitangent * offsetTexels.y) * q.texel;
    return storedToLinear(type, L, texture(cube, dir).r);
  }
  return storedToLinear(type, L, texture(map, q.base.xy + offsetTexels * q.texel).r);
}

// The receiver's depth where the tap's light ray meets the receiver plane (or the centre depth).
float receiverDepth(int type, ShadowLight L, ShadowQuery q, vec2 o) {
#ifdef RECEIVER_PLANE
  if (o == vec2(0.0)) return q.depth;
  float d;
  vec3 toP = q.point - L.position;
  if (type == LIGHT_DIRECTIONAL) {
    float denom = dot(L.axis, q.plane);
    if (abs(denom) < 1e-4) return q.depth;  // the plane contains the light direction: no intersection
    d = q.depth - dot(L.right * o.x + L.up * o.y, q.plane) * q.texelWorld / denom;
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

float tapCompare(int type, ShadowLight L, sampler2D map, samplerCube cube, ShadowQuery q, vec2 offsetTexels) {
  return receiverDepth(type, L, q, offsetTexels) - q.bias > tapLinear(type, L, map, cube, q, offsetTexels) ? 0.0 : 1.0;
}

// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation that turns Poisson banding into
// fine noise.
float pixelAngle() {
  return 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

vec2 rotated(vec2 v, float a) {
  float c = cos(a), s = sin(a);
  return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

float visibility(int type, ShadowLight L, sampler2D map, samplerCube cube, sampler2DShadow cmp,
                 samplerCubeShadow cmpCube, vec3 P, vec3 N, out ShadowDebug dbg) {
  ShadowQuery q = makeQuery(type, L, P, N);
  dbg.heat = (q.depth - q.bias - tapLinear(type, L, map, cube, q, vec2(0.0))) / max(q.texelWorld, 1e-30);
  dbg.blocker = -1.0;
  dbg.penumbra = 0.0;
#ifdef FAR_FIX
  if (q.beyondFar) return 1.0;  // nothing beyond the far plane was drawn into the map: call it lit
#endif
#if defined(FILTER_HW_PCF)
  // One tap; the sampler compares the four nearest texels and blends the results bilinearly.
  float ref = linearToStored(type, L, q.depth - q.bias);
  return type == LIGHT_POINT ? texture(cmpCube, vec4(q.base, ref)) : texture(cmp, vec3(q.base.xy, ref));
#elif defined(FILTER_PCF)
  float lit = 0.0;
  for (int i = 0; i < PCF_SIZE; ++i)
    for (int j = 0; j < PCF_SIZE; ++j)
      lit += tapCompare(type, L, map, cube, q, vec2(i, j) - 0.5 * float(PCF_SIZE - 1));
  return lit / float(PCF_SIZE * PCF_SIZE);
#elif defined(FILTER_POISSON)
#ifdef ROTATE_SAMPLES
  float angle = pixelAngle();
#else
  float angle = 0.0;
#endif
  float lit = 0.0;
  for (int k = 0; k < POISSON_COUNT; ++k)
    lit += tapCompare(type, L, map, cube, q, rotated(u_poisson[k], angle) * u_filterRadius);
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
  // 1. Blocker search: the average depth of what lies between the receiver and the light.
  float sum = 0.0, count = 0.0;
  for (int k = 0; k < BLOCKER_COUNT; ++k) {
    float d = tapLinear(type, L, map, cube, q, rotated(u_poisson[k], angle) * searchTexels);
    if (d < dR - q.bias) {
      sum += d;
      count += 1.0;
    }
  }
  if (count == 0.0) return 1.0;
  float dB = max(sum / count, 1e-30);  // > 0 by construction; guarded for the division below
  dbg.blocker = clamp((dB - n) / (L.farPlane - n), 0.0, 1.0);
  // 2. Penumbra width by similar triangles; zero when the blocker touches the receiver.
  float penumbra = type == LIGHT_DIRECTIONAL ? L.radius * max(dR - dB, 0.0) : L.radius * max(dR - dB, 0.0) / (dB * dR);
  float filterTexels = penumbra * toTexels;
  dbg.penumbra = filterTexels;
  // 3. PCF over that width.
  float lit = 0.0;
  for (int k = 0; k < PCSS_COUNT; ++k)
    lit += tapCompare(type, L, map, cube, q, rotated(u_poisson[k], angle) * filterTexels);
  return lit / float(PCSS_COUNT);
#else
  return tapCompare(type, L, map, cube, q, vec2(0.0));
#endif
}
