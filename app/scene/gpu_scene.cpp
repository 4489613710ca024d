#include "scene/gpu_scene.h"

#include <algorithm>

namespace shadelab {

static GpuMesh uploadMesh(const MeshData& m) {
  GpuMesh g;
  g.vao = gl::VertexArray::make();
  g.vertices = gl::Buffer::make();
  g.indices = gl::Buffer::make();
  g.hasUvs = !m.uvs.empty();
  g.hasTangents = !m.tangents.empty();
  g.indexCount = GLsizei(m.indices.size());
  // One buffer, attribute arrays one after another (positions | normals | uvs | tangents).
  const size_t n = m.positions.size();
  const size_t sizes[4] = {n * sizeof(glm::vec3), m.normals.size() * sizeof(glm::vec3), m.uvs.size() * sizeof(glm::vec2),
                           m.tangents.size() * sizeof(glm::vec4)};
  const void* data[4] = {m.positions.data(), m.normals.data(), m.uvs.data(), m.tangents.data()};
  const GLint comps[4] = {3, 3, 2, 4};
  glBindVertexArray(g.vao.get());
  glBindBuffer(GL_ARRAY_BUFFER, g.vertices.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sizes[0] + sizes[1] + sizes[2] + sizes[3]), nullptr, GL_STATIC_DRAW);
  size_t offset = 0;
  for (GLuint a = 0; a < 4; ++a) {
    if (sizes[a] == 0) continue;
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offset), GLsizeiptr(sizes[a]), data[a]);
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, comps[a], GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(offset));
    offset += sizes[a];
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(uint32_t)), m.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  return g;
}

std::string GpuScene::upload(const Scene& scene, const SceneNeeds& needs, std::vector<std::string>& warnings) {
  meshes_.clear();
  textures_.clear();
  for (auto& m : scene.meshes) meshes_.push_back(uploadMesh(m));
  textures_.resize(scene.images.size());
  for (auto& mat : scene.materials) {
    for (auto [image, wanted, srgb] : {std::tuple{mat.baseColorImage, needs.baseColorTextures, true},
                                       std::tuple{mat.normalImage, needs.normalTextures, false}}) {
      if (!wanted || image < 0 || textures_[size_t(image)]) continue;
      std::vector<unsigned char> rgba;
      glm::ivec2 size;
      if (auto err = decodeImage(scene.images[size_t(image)], rgba, size); !err.empty()) {
        warnings.push_back(err + "; drawing the material untextured");
        continue;
      }
      // Our images are rows top-down; GL's first row is v = 0 at the bottom. Flip once here.
      const size_t stride = size_t(size.x) * 4;
      std::vector<unsigned char> flipped(rgba.size());
      for (int y = 0; y < size.y; ++y)
        std::copy_n(rgba.begin() + ptrdiff_t(size_t(size.y - 1 - y) * stride), stride, flipped.begin() + ptrdiff_t(size_t(y) * stride));
      textures_[size_t(image)] = gl::Texture2D::fromRgba8(size, flipped.data(), scene.images[size_t(image)].sampler, srgb);
    }
  }
  return {};
}

void GpuScene::draw(const Instance& instance) const {
  const GpuMesh& m = meshes_[size_t(instance.mesh)];
  glBindVertexArray(m.vao.get());
  glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
}

int GpuScene::texturesUploaded() const {
  int n = 0;
  for (auto& t : textures_) n += bool(t);
  return n;
}

}  // namespace shadelab
