// Bump mapping, the consistent form (Blinn 1978): the tangent-space normal of the surface displaced
// by u_heightScale * h(u, v) along its normal. The height's slope by central differences one texel
// apart, turned into world units by the fragment's own UV scale (`scale`: the world length of one
// unit of u and of v), so it agrees with the displaced surface by construction:
//   n = normalize(-dh/dx, -dh/dy, 1)
// Included by height.glsl (heightAt, u_heightTexel, u_heightScale); also the displaced techniques'
// normals (HEIGHT_NORMALS).
vec3 heightNormal(vec2 uv, vec2 scale) {
  // TODO(exercise surface/bump): begin
  // The tangent-space normal of the surface displaced by u_heightScale * h(u, v) along its normal:
  // the height's slope by central differences one texel apart (u_heightTexel), turned into world
  // units (u_heightScale, and `scale` = world length of one unit of u and of v), then
  //   n = normalize(-dh/dx, -dh/dy, 1)
  return vec3(0.0, 0.0, 1.0);
  // TODO(exercise surface/bump): end
}
