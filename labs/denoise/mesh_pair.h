// A user's noisy mesh and its clean reference, as two files: which vertex of one is which vertex
// of the other. Data sets come two ways (Zhang et al. 2015's pairs; scans and their ground truth):
// the same vertices in the same order (the faces may be listed differently), or the same faces in
// the same order (the vertices renumbered). Both files are read as loaded meshes; the OBJ loader's
// splitting and reordering is undone through MeshData::sourceVertex.
#pragma once
#include <string>

#include "app/scene/mesh.h"

namespace shadelab {

struct MeshPair {
  MeshData twin;               // the clean mesh's vertices and faces, at the noisy mesh's positions
  std::string how;             // "vertices in the same order" or "faces in the same order"
  double meanMoveEdges = 0.0;  // mean distance between paired vertices, in mean edges of the clean mesh
};

// Pairs `noisy` with `clean`. Returns "" and fills `pair`, or a one-line error naming both
// meshes' counts and what a pair needs. `noisyName`/`cleanName` name them in that error.
std::string pairWithClean(const MeshData& noisy, const MeshData& clean, const std::string& noisyName,
                          const std::string& cleanName, MeshPair& pair);

}  // namespace shadelab
