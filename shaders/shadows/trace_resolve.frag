#version 330 core
// The GPU truth's sums packed for the read-back: four bytes a pixel where the sums take sixteen.
// Every sum is a whole number (a sample is 0 or 1), so an 8-bit channel holds it exactly; the
// quarter step keeps it exact where a driver truncates instead of rounding.
//   in:  trace.frag's sums (R hard, G area samples, B their squares, A coverage + 1024 a pass
//        where a ray gave up)
//   out: R the hard visibility, G the area samples that saw the light (255 at most), B coverage,
//        A whether a ray gave up
uniform sampler2D u_sum;
out vec4 o_packed;

void main() {
  vec4 sum = texelFetch(u_sum, ivec2(gl_FragCoord.xy), 0);
  float gaveUp = floor(sum.a / 1024.0);
  float covered = sum.a - 1024.0 * gaveUp > 0.5 ? 1.0 : 0.0;
  o_packed = vec4(sum.r, (sum.g + 0.25) / 255.0, covered, gaveUp > 0.0 ? 1.0 : 0.0);
}
