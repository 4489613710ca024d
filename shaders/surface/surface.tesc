#version 410 core
// Surface-detail lab, tessellation control: every edge and the inside split into u_tessLevel
// parts (1..64, the hardware's limit). One level for the whole patch, so neighbours agree on their
// shared edge and nothing cracks.
layout(vertices = 3) out;

uniform float u_tessLevel;

in Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} tcin[];

out Surface {
  vec3 world;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 compareTangent;
  vec2 uvScale;
} tcout[];

void main() {
  tcout[gl_InvocationID].world = tcin[gl_InvocationID].world;
  tcout[gl_InvocationID].normal = tcin[gl_InvocationID].normal;
  tcout[gl_InvocationID].uv = tcin[gl_InvocationID].uv;
  tcout[gl_InvocationID].tangent = tcin[gl_InvocationID].tangent;
  tcout[gl_InvocationID].compareTangent = tcin[gl_InvocationID].compareTangent;
  tcout[gl_InvocationID].uvScale = tcin[gl_InvocationID].uvScale;
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = u_tessLevel;
    gl_TessLevelInner[0] = u_tessLevel;
  }
}
