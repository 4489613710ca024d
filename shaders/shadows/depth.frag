#version 330 core
// Shadows lab, depth pass. A 2D map keeps the rasteriser's depth (linear for an orthographic
// light, 1/z-shaped for a perspective one). A cube map stores distance / far, linear, so all six
// faces compare alike.
#if defined(CUBE_MAP) || defined(CUBE_FACE)
in vec3 g_worldPos;
uniform vec3 u_lightPos;
uniform float u_far;
#endif

void main() {
#if defined(CUBE_MAP) || defined(CUBE_FACE)
  gl_FragDepth = length(g_worldPos - u_lightPos) / u_far;
#endif
}
