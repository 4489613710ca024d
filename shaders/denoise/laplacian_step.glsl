// One explicit Laplacian step of one vertex, the homework's update (labs/denoise/laplacian.h):
//   delta = p - m                      m: the weighted mean of p's one-ring neighbours
//   p'    = p - lambda <delta, n> n    along the unit vertex normal n (ALONG_NORMAL)
//   p'    = p - lambda delta           in all three coordinates otherwise: shrinks and drifts
// Also returns the vertex's share of the smoothing energy, <delta, n>^2 (|delta|^2 without
// ALONG_NORMAL): the sum over the mesh is how divergence is seen, step by step.
// Written by smooth_step.frag for every vertex at once; lambda < 0 is Taubin's un-shrinking mu step.
vec3 laplacianStep(vec3 p, vec3 neighbourMean, vec3 n, float lambda, out float energy) {
  vec3 delta = p - neighbourMean;
#ifdef ALONG_NORMAL
  float along = dot(delta, n);
  energy = along * along;
  return p - lambda * along * n;
#else
  energy = dot(delta, delta);
  return p - lambda * delta;
#endif
}
