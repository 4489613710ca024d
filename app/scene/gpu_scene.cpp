#include "scene/gpu_scene.h"

#include <algorithm>

namespace shadelab {

std::string GpuScene::upload(const Scene& scene, const SceneNeeds& needs, std::vector<std::string>& warnings) {
  meshes_.clear();
  textures_.clear();
  for (auto& m : scene.meshes) meshes_.push_back(GpuMesh::upload(m));
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

int GpuScene::texturesUploaded() const {
  int n = 0;
  for (auto& t : textures_) n += bool(t);
  return n;
}

}  // namespace shadelab
