#version 410 core
// Surface-detail lab: the tangent frame overlay. One point per vertex; tbn.geom turns each into
// three short lines, T red, B green, N blue.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 3) in vec4 a_tangent;

uniform mat4 u_model;
uniform mat3 u_normalMatrix;

out Vertex {
  vec3 world;
  vec3 t, b, n;
} vout;

void main() {
  vout.world = (u_model * vec4(a_position, 1.0)).xyz;
  vec3 n = normalize(u_normalMatrix * a_normal);
  vec3 t = mat3(u_model) * a_tangent.xyz;
  t = length(t) > 1e-8 ? normalize(t - n * dot(n, t)) : vec3(0.0);
  vout.t = t;
  vout.b = cross(n, t) * (a_tangent.w < 0.0 ? -1.0 : 1.0);
  vout.n = n;
}
