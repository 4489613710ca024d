// Steep parallax and parallax occlusion mapping: march the view ray down through `layers` depth
// slices until it is under the height field; POM then interpolates between the last two slices.
// The loop is bounded by `layers` whatever the angle.
vec2 parallaxMarch(vec2 uv, vec3 viewTs, vec2 scale, int layers, bool occlusion, out float depth) {
  float layerDepth = 1.0 / float(layers);
  vec2 step = parallaxDirection(viewTs, scale) * layerDepth;
  // TODO(exercise surface/pom): begin
  // March the view ray down from depth 0 at uv, one layer (layerDepth deeper, `step` along the
  // texture) at a time, at most `layers` times, until the ray's depth reaches the surface's depth
  // there (1 - heightAt). Steep parallax (occlusion false) returns that point. POM interpolates
  // between this layer and the one before, where the ray crossed the surface. Set `depth` to the
  // ray's depth at the point returned.
  depth = 0.0;
  return uv;
  // TODO(exercise surface/pom): end
}
