// One mesh on the GPU: a vertex array over one vertex buffer (positions | normals | uvs |
// tangents, absent arrays left out) and an index buffer. A lab that derives geometry from the
// scene (a noisy copy, a smoothed result, a displaced grid) owns GpuMeshes of its own and, when
// only positions or normals change, replaces those arrays in place: no reallocation, no scene
// rebuild. Extra per-vertex floats (an offset, a seam gap) get buffers of their own.
#pragma once
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/handle.h"
#include "app/scene/mesh.h"

namespace shadelab {

// Attribute locations every lab's vertex shaders use.
enum AttributeLocation : GLuint {
  kPosition = 0,
  kNormal = 1,
  kUv = 2,
  kTangent = 3,
  kScalar0 = 4,
  kScalar1 = 5,  // lab-defined floats (an offset, a seam gap, a UV scale)
  kVector0 = 6,  // a lab-defined vec4 (a second tangent frame)
};

enum class Primitive {
  Triangles,
  Patches,  // three-vertex patches for a tessellation control stage
  Points,   // every vertex once, no indices (point views, transform-feedback read-backs)
};

class GpuMesh {
 public:
  GpuMesh() = default;
  static GpuMesh upload(const MeshData& mesh);

  // Replace one array of the same length in place (glBufferSubData). Returns false, changing
  // nothing, when the length differs from the uploaded vertex count or the array was not uploaded.
  bool updatePositions(std::span<const glm::vec3> positions);
  bool updateNormals(std::span<const glm::vec3> normals);
  // `components` floats per vertex at `location` (kScalar0, kScalar1: 1; kVector0: 4), in a buffer
  // of its own: made on first use, then replaced in place.
  bool setAttribute(GLuint location, int components, std::span<const float> values);
  bool setScalars(GLuint location, std::span<const float> values) { return setAttribute(location, 1, values); }

  void draw(Primitive primitive = Primitive::Triangles) const;
  // Triangles (or patches) [first, first + count) of the index buffer, clamped to what there is.
  void drawTriangles(Primitive primitive, size_t first, size_t count) const;
  size_t triangleCount() const { return size_t(indexCount_) / 3; }
  explicit operator bool() const { return bool(vao_); }
  size_t vertexCount() const { return vertexCount_; }
  GLsizei indexCount() const { return indexCount_; }
  bool hasUvs() const { return offsets_[kUv] != kAbsent; }
  bool hasTangents() const { return offsets_[kTangent] != kAbsent; }

 private:
  static constexpr size_t kAbsent = ~size_t(0);
  bool replace(GLuint attribute, const void* data, size_t bytes, size_t count);

  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_;
  gl::Buffer extras_[3];                                      // kScalar0, kScalar1, kVector0
  size_t offsets_[4] = {kAbsent, kAbsent, kAbsent, kAbsent};  // byte offset of each array
  size_t vertexCount_ = 0;
  GLsizei indexCount_ = 0;
};

}  // namespace shadelab
