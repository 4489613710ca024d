// Finer versions of a mesh for displacement, and how big a unit of UV is on it and how sheared.
//
// Midpoint subdivision splits every triangle into four at its edge midpoints, `levels` times;
// neighbours share midpoints, so nothing cracks. Positions, UVs, normals (renormalised) and
// tangents are interpolated: the surface stays the base mesh, only finer, and a displacement
// p + n s h(uv) on it converges to the displaced base mesh as levels grow.
#pragma once
#include <vector>

#include "app/scene/mesh.h"

namespace shadelab {

MeshData subdivide(const MeshData& mesh, int levels);

// Tessellation at level `parts` done on the CPU where there are no tessellation stages (WebGL2): every edge cut into
// `parts` equal pieces, as the tessellator's equal spacing cuts it, and the triangle into parts^2 on a regular grid
// (the tessellator places its inner points on concentric rings instead: the two sample the height field differently at
// a low level and agree as it rises). Attributes are interpolated linearly from the corners (normals and tangents
// renormalised). Neighbours compute their shared edge's points from the same endpoints in the
// same order, so nothing cracks.
MeshData splitEdges(const MeshData& mesh, int parts);

// Per vertex, the world length of one unit of u and of v (|dp/du|, |dp/dv|), weighted over its
// triangles by angle. A height of s world units is s / scale in UV units: what bump mapping and
// parallax need to mean the same depth as displacement does.
std::vector<glm::vec2> uvScale(const MeshData& mesh);

// Per triangle with UVs of non-zero area, the angle in degrees between dp/du (a generated
// tangent's direction) and the gradient of u in the triangle's plane (a screen-space "cotangent"
// frame's): the shear of the UV mapping. Zero where the mapping is orthogonal.
std::vector<float> uvShearDegrees(const MeshData& mesh);

// Subdivision levels that bring the mesh's edges down to about one texel of a `texels`-wide map.
int levelsForTexelSize(const MeshData& mesh, int texels, int maxLevels);

}  // namespace shadelab
