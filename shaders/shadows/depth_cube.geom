#version 330 core
// Point-light shadows in one pass: every triangle is emitted once per cube face, gl_Layer picks
// the face. Six passes would cost six vertex submissions instead; on llvmpipe the single pass
// is the cheaper of the two for scenes this size.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

uniform mat4 u_faceViewProj[6];
out vec3 g_worldPos;

void main() {
  for (int face = 0; face < 6; ++face) {
    for (int i = 0; i < 3; ++i) {
      gl_Layer = face;
      g_worldPos = gl_in[i].gl_Position.xyz;
      gl_Position = u_faceViewProj[face] * gl_in[i].gl_Position;
      EmitVertex();
    }
    EndPrimitive();
  }
}
