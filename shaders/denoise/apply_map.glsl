// The denoised mesh from the noisy one and the displacement map baked from the smoothing: each
// vertex moves along its (noisy) normal by the offset the map holds at its UV,
//   p' = p + n (stored * u_scale + u_bias)
// The bake stores each offset o as (o - bias) / scale so that it fits the map's format (a value in
// [0, 1] for 8 and 16 bits; scale 1 and bias 0 for float maps): this undoes it. Where copies of a
// position on a UV seam read different texels, they move apart and the mesh cracks.
// Called by mesh.vert with DISPLACE_MAP; p and n in world space (the lab draws with no model
// matrix), n of unit length. A vertex stage has no screen-space derivatives: read level 0.
uniform sampler2D u_displacement;  // one channel; nearest or bilinear as the lab sets it
uniform float u_scale;
uniform float u_bias;

vec3 displacedByMap(vec3 p, vec3 n, vec2 uv) {
  float stored = textureLod(u_displacement, uv, 0.0).r;
  return p + n * (stored * u_scale + u_bias);
}
