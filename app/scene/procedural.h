// Primitives the project makes itself, at any tessellation, with exact normals and UVs.
#pragma once
#include "app/scene/mesh.h"
#include "app/scene/scene.h"

namespace shadelab {

MeshData makeUvSphere(float radius, int segments);           // segments around; segments/2 rings
MeshData makeTorus(float major, float minor, int segments);  // segments around the ring; half that around the tube
MeshData makeBox(glm::vec3 halfExtent);                      // 24 vertices, flat faces
MeshData makePlane(float size, int cells, float uvRepeat);   // y = 0, facing +Y, cells x cells quads
ImageSource makeCheckerImage(int size, int checks);          // black/white, for perspective-correct UVs

}  // namespace shadelab
