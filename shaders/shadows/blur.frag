#version 330 core
// Shadows lab: one direction of a separable Gaussian blur over one layer of a moment map
// (sigma = radius / 2, 2 radius + 1 taps). Run across, then down.
uniform sampler2DArray u_src;
uniform int u_layer;
uniform vec2 u_direction;  // (1, 0) or (0, 1)
uniform int u_radius;      // texels each way, 1..32
out vec4 o_moments;

void main() {
  ivec2 size = textureSize(u_src, 0).xy;
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 step = ivec2(u_direction);
  float sigma = max(float(u_radius) * 0.5, 0.5);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int k = -u_radius; k <= u_radius; ++k) {
    float w = exp(-0.5 * float(k * k) / (sigma * sigma));
    ivec2 q = clamp(p + step * k, ivec2(0), size - 1);  // the map's edge repeats
    sum += w * texelFetch(u_src, ivec3(q, u_layer), 0);
    weights += w;
  }
  o_moments = sum / weights;
}
