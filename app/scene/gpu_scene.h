// A Scene uploaded for drawing: one GpuMesh per mesh (attribute locations in scene/gpu_mesh.h;
// absent arrays are not uploaded) and the textures the needs asked for.
#pragma once
#include <string>
#include <vector>

#include "app/gl/texture.h"
#include "app/scene/gpu_mesh.h"
#include "app/scene/scene.h"

namespace shadelab {

class GpuScene {
 public:
  // Uploads meshes, decodes and uploads only the images `needs` asks for. Returns "" or an
  // error naming the file (a broken texture becomes a warning and the material goes untextured).
  std::string upload(const Scene& scene, const SceneNeeds& needs, std::vector<std::string>& warnings);
  // Re-samples every uploaded texture: the file's sampler with `sampling` over it.
  void applySampling(const Scene& scene, const SceneNeeds& needs);
  void draw(const Instance& instance, Primitive primitive = Primitive::Triangles) const {
    meshes_[size_t(instance.mesh)].draw(primitive);
  }
  const GpuMesh& mesh(int index) const { return meshes_[size_t(index)]; }
  // The uploaded base-colour texture of a material, or null.
  const gl::Texture2D* baseColorTexture(const Material& m) const { return texture(m.baseColorImage); }
  const gl::Texture2D* normalTexture(const Material& m) const { return texture(m.normalImage); }
  const gl::Texture2D* heightTexture(const Material& m) const {
    return m.heightImage >= 0 && size_t(m.heightImage) < heights_.size() && heights_[size_t(m.heightImage)]
               ? &heights_[size_t(m.heightImage)]
               : nullptr;
  }
  int texturesUploaded() const;

 private:
  const gl::Texture2D* texture(int image) const {
    return image >= 0 && size_t(image) < textures_.size() && textures_[size_t(image)] ? &textures_[size_t(image)]
                                                                                      : nullptr;
  }
  std::vector<GpuMesh> meshes_;
  std::vector<gl::Texture2D> textures_;  // by Scene::images index; empty when not needed
  std::vector<gl::Texture2D> heights_;   // height maps, one channel, by Scene::images index
};

}  // namespace shadelab
