#include "app/scene/scene.h"

#include <algorithm>

#include <stb_image.h>

namespace shadelab {

Bounds Scene::boundsOfInstance(size_t i) const {
  const Instance& inst = instances[i];
  const Bounds mb = meshes[size_t(inst.mesh)].bounds();
  Bounds b;
  if (!mb.empty())
    for (int c = 0; c < 8; ++c) b.extend(glm::vec3(inst.model * glm::vec4(mb.corner(c), 1.0f)));
  return b;
}

Bounds Scene::computeBounds() const {
  Bounds b;
  for (size_t i = 0; i < instances.size(); ++i)
    if (const Bounds ib = boundsOfInstance(i); !ib.empty()) {
      b.extend(ib.min);
      b.extend(ib.max);
    }
  return b;
}

std::vector<size_t> Scene::nearestFirst(glm::vec3 eye) const {
  std::vector<std::pair<float, size_t>> keyed;
  keyed.reserve(instances.size());
  for (size_t i = 0; i < instances.size(); ++i) {
    // The boxes the host keeps; without them (a scene not built by the host) the model's origin,
    // rather than a walk over every vertex each frame.
    const bool boxed = i < instanceBounds.size() && !instanceBounds[i].empty();
    const glm::vec3 d = (boxed ? instanceBounds[i].center() : glm::vec3(instances[i].model[3])) - eye;
    keyed.emplace_back(glm::dot(d, d), i);
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<size_t> order;
  order.reserve(keyed.size());
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (auto& inst : instances) n += meshes[size_t(inst.mesh)].triangleCount();
  return n;
}

std::string decodeImage(const ImageSource& src, std::vector<unsigned char>& rgba, glm::ivec2& size) {
  if (!src.rgba.empty()) {
    rgba = src.rgba;
    size = src.size;
    return {};
  }
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = nullptr;
  if (!src.bytes.empty())
    pixels = stbi_load_from_memory(src.bytes.data(), int(src.bytes.size()), &w, &h, &channels, 4);
  else
    pixels = stbi_load(src.file.c_str(), &w, &h, &channels, 4);
  if (!pixels) {
    const std::string where = src.file.empty() ? src.name : src.file.string();
    return where + ": cannot decode image (" + (stbi_failure_reason() ? stbi_failure_reason() : "unknown") +
           "; valid: PNG, JPEG, TGA, BMP)";
  }
  rgba.assign(pixels, pixels + size_t(w) * h * 4);
  size = {w, h};
  stbi_image_free(pixels);
  return {};
}

}  // namespace shadelab
