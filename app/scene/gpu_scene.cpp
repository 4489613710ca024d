#include "app/scene/gpu_scene.h"

#include <algorithm>

namespace shadelab {

// Our images are rows top-down; GL's first row is v = 0 at the bottom. Flip once, at upload.
std::vector<unsigned char> flipRows(const std::vector<unsigned char>& rgba, glm::ivec2 size, int channels) {
  const size_t stride = size_t(size.x) * size_t(channels);
  std::vector<unsigned char> out(rgba.size());
  for (int y = 0; y < size.y; ++y)
    std::copy_n(rgba.begin() + ptrdiff_t(size_t(size.y - 1 - y) * stride), stride,
                out.begin() + ptrdiff_t(size_t(y) * stride));
  return out;
}

namespace {

// The file's sampler, with the lab's overrides on top; no mip filter without a mip chain.
gl::SamplerState samplerFor(const ImageSource& image, const SceneNeeds& needs) {
  gl::SamplerState s = image.sampler;
  const TextureSampling& o = needs.sampling;
  if (o.minFilter) s.minFilter = o.minFilter;
  if (o.magFilter) s.magFilter = o.magFilter;
  if (o.wrap) s.wrapS = s.wrapT = o.wrap;
  s.maxAnisotropy = std::max(o.anisotropy, 1.0f);
  if (!needs.mipmaps)
    s.minFilter =
        s.minFilter == GL_NEAREST || s.minFilter == GL_NEAREST_MIPMAP_NEAREST || s.minFilter == GL_NEAREST_MIPMAP_LINEAR
            ? GL_NEAREST
            : GL_LINEAR;
  return s;
}

}  // namespace

std::string GpuScene::upload(const Scene& scene, const SceneNeeds& needs, std::vector<std::string>& warnings) {
  meshes_.clear();
  textures_.clear();
  heights_.clear();
  for (auto& m : scene.meshes) meshes_.push_back(GpuMesh::upload(m));
  textures_.resize(scene.images.size());
  heights_.resize(scene.images.size());
  for (auto& mat : scene.materials) {
    for (auto [image, wanted, srgb] : {std::tuple{mat.baseColorImage, needs.baseColorTextures, true},
                                       std::tuple{mat.normalImage, needs.normalTextures, needs.normalMapsAsSrgb}}) {
      if (!wanted || image < 0 || textures_[size_t(image)]) continue;
      std::vector<unsigned char> rgba;
      glm::ivec2 size;
      if (auto err = decodeImage(scene.images[size_t(image)], rgba, size); !err.empty()) {
        warnings.push_back(err + "; drawing the material untextured");
        continue;
      }
      if (image == mat.normalImage && mat.normalGreenDown)  // every normal map on the GPU is OpenGL's +Y
        for (size_t i = 1; i < rgba.size(); i += 4) rgba[i] = uint8_t(255 - rgba[i]);
      gl::SamplerState s = samplerFor(scene.images[size_t(image)], needs);
      if (needs.mipmaps && (s.minFilter == GL_LINEAR || s.minFilter == GL_NEAREST))
        s.minFilter = GL_LINEAR_MIPMAP_LINEAR;  // build the chain; applySampling sets the asked filter
      textures_[size_t(image)] = gl::Texture2D::fromRgba8(size, flipRows(rgba, size, 4).data(), s, srgb);
      textures_[size_t(image)].setSampler(samplerFor(scene.images[size_t(image)], needs));
    }
    const int h = mat.heightImage;
    if (!needs.heightTextures || h < 0 || heights_[size_t(h)]) continue;
    std::vector<unsigned char> rgba;
    glm::ivec2 size;
    if (auto err = decodeImage(scene.images[size_t(h)], rgba, size); !err.empty()) {
      warnings.push_back(err + "; the material has no height map");
      continue;
    }
    const bool depth = needs.heightConvention == HeightConvention::Depth ||
                       (needs.heightConvention == HeightConvention::AsLoaded && mat.heightIsDepth);
    std::vector<unsigned char> red(size_t(size.x) * size_t(size.y));
    for (size_t i = 0; i < red.size(); ++i) red[i] = depth ? 255 - rgba[4 * i] : rgba[4 * i];
    gl::SamplerState s = samplerFor(scene.images[size_t(h)], needs);
    const gl::SamplerState asked = s;
    if (needs.mipmaps && (s.minFilter == GL_LINEAR || s.minFilter == GL_NEAREST)) s.minFilter = GL_LINEAR_MIPMAP_LINEAR;
    heights_[size_t(h)] =
        gl::Texture2D::fromData(size, GL_R8, GL_RED, GL_UNSIGNED_BYTE, flipRows(red, size, 1).data(), s);
    heights_[size_t(h)].setSampler(asked);
  }
  return {};
}

void GpuScene::applySampling(const Scene& scene, const SceneNeeds& needs) {
  for (size_t i = 0; i < scene.images.size(); ++i) {
    if (i < textures_.size() && textures_[i]) textures_[i].setSampler(samplerFor(scene.images[i], needs));
    if (i < heights_.size() && heights_[i]) heights_[i].setSampler(samplerFor(scene.images[i], needs));
  }
}

int GpuScene::texturesUploaded() const {
  int n = 0;
  for (auto& t : textures_) n += bool(t);
  for (auto& t : heights_) n += bool(t);
  return n;
}

}  // namespace shadelab
