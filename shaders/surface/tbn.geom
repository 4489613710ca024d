#version 410 core
// Three lines from every vertex: its tangent (red), bitangent (green) and normal (blue).
layout(points) in;
layout(line_strip, max_vertices = 6) out;

uniform mat4 u_viewProj;
uniform float u_length;

in Vertex {
  vec3 world;
  vec3 t, b, n;
} gin[];

out vec3 g_color;

void line(vec3 dir, vec3 color) {
  g_color = color;
  gl_Position = u_viewProj * vec4(gin[0].world, 1.0);
  EmitVertex();
  gl_Position = u_viewProj * vec4(gin[0].world + dir * u_length, 1.0);
  EmitVertex();
  EndPrimitive();
}

void main() {
  line(gin[0].t, vec3(1.0, 0.2, 0.2));
  line(gin[0].b, vec3(0.2, 1.0, 0.2));
  line(gin[0].n, vec3(0.3, 0.5, 1.0));
}
