#include "app/scene/gpu_scene.h"

#include <algorithm>

#include "app/scene/mip_chain.h"

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

// An 8-bit texture (`channels` 1 or 4, rows bottom-up), with its mip chain made here when the
// sampler filters between levels: the box filter in linear light (sRGB decoded first) that a
// driver's glGenerateMipmap uses, without the blit a software driver compiles in every new context
// (llvmpipe: about a quarter of a second, nearly all of a process's first upload).
gl::Texture2D texture8(glm::ivec2 size, std::vector<unsigned char> pixels, int channels, bool srgb,
                       const gl::SamplerState& s) {
  const GLenum internal = channels == 1 ? GL_R8 : srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
  const GLenum format = channels == 1 ? GL_RED : GL_RGBA;
  if (s.minFilter == GL_LINEAR || s.minFilter == GL_NEAREST)
    return gl::Texture2D::fromData(size, internal, format, GL_UNSIGNED_BYTE, pixels.data(), s);
  const std::vector<LinearImage> chain =
      buildMipChain(srgb ? decodeSrgb8(size, pixels) : decodeLinear8(size, pixels, channels), MipDownsampler::Box);
  std::vector<std::vector<unsigned char>> bytes;
  bytes.push_back(std::move(pixels));
  for (size_t k = 1; k < chain.size(); ++k)
    bytes.push_back(srgb ? encodeSrgb8(chain[k]) : encodeLinear8(chain[k], channels));
  std::vector<const void*> levels;
  for (auto& b : bytes) levels.push_back(b.data());
  return gl::Texture2D::fromLevels(size, internal, format, GL_UNSIGNED_BYTE, levels, s);
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
      textures_[size_t(image)] = texture8(size, flipRows(rgba, size, 4), 4, srgb, s);
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
    heights_[size_t(h)] = texture8(size, flipRows(red, size, 1), 1, false, s);
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
