// One explicit Laplacian step of one vertex, the homework's update (labs/denoise/laplacian.h):
//   delta = p - m                      m: the weighted mean of p's one-ring neighbours
//   p'    = p - lambda <delta, n> n    along the unit vertex normal n (ALONG_NORMAL)
//   p'    = p - lambda delta           in all three coordinates otherwise: shrinks and drifts
// Also returns the vertex's share of the smoothing energy, <delta, n>^2 (|delta|^2 without
// ALONG_NORMAL): the sum over the mesh is how divergence is seen, step by step.
// Written by smooth_step.frag for every vertex at once; lambda < 0 is Taubin's un-shrinking mu step.
vec3 laplacianStep(vec3 p, vec3 neighbourMean, vec3 n, float lambda, out float energy) {
  // TODO(exercise denoise/laplacian): begin
  // The umbrella vector delta = p - neighbourMean, the step along n (ALONG_NORMAL) or along delta
  // itself (#else), and the energy of this vertex before the step.
  energy = 0.0;
  return p;  // not moved: the mesh stays as noisy as it came
  // TODO(exercise denoise/laplacian): end
}
