// How far a denoised mesh is from the clean one it was made from, vertex for vertex and face for
// face (the meshes share their connectivity).
//
// The angle metric is the one of the Guided Mesh Normal Filtering paper's code (Zhang et al. 2015):
// the mean, over faces paired by index, of the angle in degrees between the result's unit face
// normal and the clean mesh's. It reproduces the values published for the noisy inputs in
// ../shared/data/denoise (tests/unit/denoise_test.cpp checks all seven).
#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

struct MeshError {
  double angleDeg = 0;     // mean face-normal angle to the clean mesh
  double rmsDistance = 0;  // vertex to its clean position, in `unit`s
  double maxDistance = 0;
  double volumeChangePct = 0;  // signed volume against the clean mesh's (cone from its centroid if open)
  size_t degenerateFaces = 0;  // faces with no normal in either mesh, left out of the mean angle
};

double meanFaceNormalAngleDeg(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b,
                              std::span<const uint32_t> indices, size_t* degenerate = nullptr);
MeshError meshError(std::span<const glm::dvec3> result, std::span<const glm::dvec3> clean,
                    std::span<const uint32_t> indices, double unit);
double signedVolume(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices, const glm::dvec3& origin);

}  // namespace shadelab
