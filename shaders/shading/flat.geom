#version 330 core
// Shading lab, flat mode: one lighting evaluation per triangle, at its centroid, with the true
// face normal (not any vertex's). The result is passed on `flat`, so every fragment of the face
// gets exactly this colour. Zero-area triangles (the poles of a UV sphere) have no normal:
// safeNormalize falls back to the averaged vertex normal rather than producing NaN.
// The cross product's sign follows the winding, which files do not always keep consistent; the
// face normal is turned to agree with the vertex normals instead. Two-sided, as in the other
// modes: a face seen from behind is lit on the side the eye sees.
#include "common/lighting.glsl"
#include "shading/interpolation.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

uniform vec3 u_eye;

in Vertex {
  vec3 worldPos;
  vec3 normal;
  vec2 uv;
#ifdef SCREEN_LINEAR_UV
  SCREEN_LINEAR uvLinear;  // interpolation.glsl
#endif
} gin[];

out Surface {
  vec3 worldPos;
  vec3 normal;
  vec2 uv;
#ifdef SCREEN_LINEAR_UV
  SCREEN_LINEAR uvLinear;  // interpolation.glsl
#endif
  flat vec3 diffuse;
  flat vec3 specular;
} gout;

void main() {
  vec3 center = (gin[0].worldPos + gin[1].worldPos + gin[2].worldPos) / 3.0;
  vec3 averaged = gin[0].normal + gin[1].normal + gin[2].normal;
  vec3 face = cross(gin[1].worldPos - gin[0].worldPos, gin[2].worldPos - gin[0].worldPos);
  vec3 N = safeNormalize(face, safeNormalize(averaged, vec3(0.0, 1.0, 0.0)));
  if (dot(N, averaged) < 0.0) N = -N;        // the winding disagrees with the normals: trust the normals
  if (dot(N, u_eye - center) < 0.0) N = -N;  // seen from behind: light the side we see
  Reflected lit = reflectLights(center, N, u_eye);
  for (int i = 0; i < 3; ++i) {
    gout.worldPos = gin[i].worldPos;
    gout.normal = N;
    gout.uv = gin[i].uv;
#ifdef SCREEN_LINEAR_UV
    gout.uvLinear = gin[i].uvLinear;
#endif
    gout.diffuse = lit.diffuse;
    gout.specular = lit.specular;
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
