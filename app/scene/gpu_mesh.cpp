#include "app/scene/gpu_mesh.h"

#include <algorithm>

namespace shadelab {

GpuMesh GpuMesh::upload(const MeshData& m) {
  GpuMesh g;
  g.vao_ = gl::VertexArray::make();
  g.vertices_ = gl::Buffer::make();
  g.indices_ = gl::Buffer::make();
  g.vertexCount_ = m.positions.size();
  g.indexCount_ = GLsizei(m.indices.size());
  const size_t sizes[4] = {m.positions.size() * sizeof(glm::vec3), m.normals.size() * sizeof(glm::vec3),
                           m.uvs.size() * sizeof(glm::vec2), m.tangents.size() * sizeof(glm::vec4)};
  const void* data[4] = {m.positions.data(), m.normals.data(), m.uvs.data(), m.tangents.data()};
  const GLint comps[4] = {3, 3, 2, 4};
  glBindVertexArray(g.vao_.get());
  glBindBuffer(GL_ARRAY_BUFFER, g.vertices_.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sizes[0] + sizes[1] + sizes[2] + sizes[3]), nullptr, GL_STATIC_DRAW);
  size_t offset = 0;
  for (GLuint a = 0; a < 4; ++a) {
    if (sizes[a] == 0) continue;
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offset), GLsizeiptr(sizes[a]), data[a]);
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, comps[a], GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(offset));
    g.offsets_[a] = offset;
    offset += sizes[a];
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices_.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(uint32_t)), m.indices.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  return g;
}

bool GpuMesh::replace(GLuint attribute, const void* data, size_t bytes, size_t count) {
  if (!vao_ || count != vertexCount_ || offsets_[attribute] == kAbsent) return false;
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
  glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offsets_[attribute]), GLsizeiptr(bytes), data);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return true;
}

bool GpuMesh::updatePositions(std::span<const glm::vec3> p) {
  return replace(kPosition, p.data(), p.size_bytes(), p.size());
}
bool GpuMesh::updateNormals(std::span<const glm::vec3> n) {
  return replace(kNormal, n.data(), n.size_bytes(), n.size());
}

bool GpuMesh::setAttribute(GLuint location, int components, std::span<const float> values) {
  if (!vao_ || location < kScalar0 || location > kVector0 || components < 1 || components > 4 ||
      values.size() != vertexCount_ * size_t(components))
    return false;
  gl::Buffer& buffer = extras_[location - kScalar0];
  if (!buffer) {
    buffer = gl::Buffer::make();
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(values.size_bytes()), values.data(), GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(values.size_bytes()), values.data());
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return true;
}

void GpuMesh::drawTriangles(Primitive primitive, size_t first, size_t count) const {
  first = std::min(first, triangleCount());
  count = std::min(count, triangleCount() - first);
  if (count == 0) return;
  glBindVertexArray(vao_.get());
  const auto offset = reinterpret_cast<const void*>(first * 3 * sizeof(uint32_t));
  if (primitive == Primitive::Patches) {
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glDrawElements(GL_PATCHES, GLsizei(count * 3), GL_UNSIGNED_INT, offset);
  } else {
    glDrawElements(GL_TRIANGLES, GLsizei(count * 3), GL_UNSIGNED_INT, offset);
  }
}

void GpuMesh::draw(Primitive primitive) const {
  glBindVertexArray(vao_.get());
  if (primitive == Primitive::Points) {
    glDrawArrays(GL_POINTS, 0, GLsizei(vertexCount_));
  } else if (primitive == Primitive::Patches) {
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glDrawElements(GL_PATCHES, indexCount_, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  }
}

}  // namespace shadelab
