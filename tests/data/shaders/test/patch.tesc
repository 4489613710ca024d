#version 410 core
// Test shader: every edge and the inside split into LEVEL parts.
layout(vertices = 3) out;
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = float(LEVEL);
    gl_TessLevelInner[0] = float(LEVEL);
  }
}
