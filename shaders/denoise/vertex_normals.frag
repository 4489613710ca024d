#version 330 core
// Denoising on the GPU: the area-weighted unit normal of every vertex, a fragment each, from the
// faces around it (laplacian.cpp's normalsOf(): the faces' cross products summed, +Z where they
// give no direction). u_faces holds, per incident face, its two other corners in winding order.
uniform sampler2D u_positions;
uniform isampler2D u_ranges;  // ring start, ring count, face start, face count
uniform isampler2D u_faces;   // the face's next corner, the one after
uniform int u_vertexCount;
out vec4 o_normal;

ivec2 texelOf(int index, int width) { return ivec2(index % width, index / width); }
vec3 positionOf(int v) { return texelFetch(u_positions, texelOf(v, textureSize(u_positions, 0).x), 0).xyz; }

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int v = texel.y * textureSize(u_positions, 0).x + texel.x;
  if (v >= u_vertexCount) {
    o_normal = vec4(0.0, 0.0, 1.0, 0.0);
    return;
  }
  vec3 p = texelFetch(u_positions, texel, 0).xyz;
  ivec4 range = texelFetch(u_ranges, texel, 0);
  int faceWidth = textureSize(u_faces, 0).x;
  vec3 n = vec3(0.0);
  for (int k = 0; k < range.w; ++k) {
    ivec2 corners = texelFetch(u_faces, texelOf(range.z + k, faceWidth), 0).xy;
    vec3 c = cross(positionOf(corners.x) - p, positionOf(corners.y) - p);
    if (!any(isnan(c)) && !any(isinf(c))) n += c;
  }
  // Scaled before its length is taken: a huge normal's squared length would overflow a float.
  float largest = max(max(abs(n.x), abs(n.y)), abs(n.z));
  o_normal = vec4(largest > 0.0 && !isinf(largest) ? normalize(n / largest) : vec3(0.0, 0.0, 1.0), 0.0);
}
