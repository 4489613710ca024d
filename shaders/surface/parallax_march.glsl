// Steep parallax and parallax occlusion mapping: march the view ray down through `layers` depth
// slices until it is under the height field; POM then interpolates between the last two slices.
// The loop is bounded by `layers` whatever the angle.
vec2 parallaxMarch(vec2 uv, vec3 viewTs, vec2 scale, int layers, bool occlusion, out float depth) {
  float layerDepth = 1.0 / float(layers);
  vec2 step = parallaxDirection(viewTs, scale) * layerDepth;
  float current = 0.0;
  vec2 at = uv;
  float surface = 1.0 - heightAt(at);
  for (int i = 0; i < layers && current < surface; ++i) {
    at -= step;
    current += layerDepth;
    surface = 1.0 - heightAt(at);
  }
  depth = current;
  if (!occlusion) return at;
  // Between the layer before (above the surface) and this one (below): where the ray crossed.
  vec2 before = at + step;
  float after = surface - current, above = (1.0 - heightAt(before)) - (current - layerDepth);
  float w = after / min(after - above, -1e-6);
  depth = mix(current, current - layerDepth, w);
  return mix(at, before, w);
}
