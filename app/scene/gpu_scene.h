// A Scene uploaded for drawing: one VAO per mesh (attribute locations 0 position, 1 normal,
// 2 uv, 3 tangent; absent arrays are not uploaded) and the textures the needs asked for.
#pragma once
#include <string>
#include <vector>

#include "gl/texture.h"
#include "scene/scene.h"

namespace shadelab {

enum AttributeLocation : GLuint { kPosition = 0, kNormal = 1, kUv = 2, kTangent = 3 };

struct GpuMesh {
  gl::VertexArray vao;
  gl::Buffer vertices;
  gl::Buffer indices;
  GLsizei indexCount = 0;
  bool hasUvs = false;
  bool hasTangents = false;
};

class GpuScene {
 public:
  // Uploads meshes, decodes and uploads only the images `needs` asks for. Returns "" or an
  // error naming the file (a broken texture becomes a warning and the material goes untextured).
  std::string upload(const Scene& scene, const SceneNeeds& needs, std::vector<std::string>& warnings);
  void draw(const Instance& instance) const;
  // The uploaded base-colour texture of a material, or null.
  const gl::Texture2D* baseColorTexture(const Material& m) const { return texture(m.baseColorImage); }
  const gl::Texture2D* normalTexture(const Material& m) const { return texture(m.normalImage); }
  int texturesUploaded() const;

 private:
  const gl::Texture2D* texture(int image) const {
    return image >= 0 && size_t(image) < textures_.size() && textures_[size_t(image)] ? &textures_[size_t(image)] : nullptr;
  }
  std::vector<GpuMesh> meshes_;
  std::vector<gl::Texture2D> textures_;  // by Scene::images index; empty when not needed
};

}  // namespace shadelab
