// A scene as the labs see it: meshes, materials, instances with their world transforms, and
// image sources that stay encoded until a lab asks for them.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/texture.h"
#include "app/scene/mesh.h"

namespace shadelab {

// How the textures a configuration uses are sampled: a lab's override of what the files ask for.
// Changing only this re-samples the uploaded textures; nothing is decoded or uploaded again.
struct TextureSampling {
  GLenum minFilter = 0;     // 0: as the file asks (usually trilinear); else GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR, ...
  GLenum magFilter = 0;     // 0: as the file asks
  GLenum wrap = 0;          // 0: as the file asks; else GL_REPEAT, GL_CLAMP_TO_EDGE, ...
  float anisotropy = 1.0f;  // 1..16, clamped to the driver's limit
  bool operator==(const TextureSampling&) const = default;
};

// What a configuration requires. The host builds exactly this, and nothing else.
// How a height map's values read: as the material says (a file's disp map is a height; LearnOpenGL's
// *_disp images are depths), or as heights or depths (white = deep: height = 1 - value) whatever it says.
enum class HeightConvention { AsLoaded, Height, Depth, Count };

struct SceneNeeds {
  bool uvs = false;                // texture coordinates (else dropped before upload)
  bool tangents = false;           // only a normal map needs them
  bool baseColorTextures = false;  // decode and upload base-colour images (sRGB)
  bool normalTextures = false;     // decode and upload normal-map images (linear)
  bool heightTextures = false;     // decode and upload height maps (one channel, linear; depth maps inverted)
  HeightConvention heightConvention = HeightConvention::AsLoaded;
  bool normalMapsAsSrgb = false;  // decode normal maps as sRGB instead: a mistake a lab can show
  bool mipmaps = true;            // build a mip chain for every texture uploaded
  TextureSampling sampling;
  int tessellation = 32;          // segments of procedural primitives (ignored by files)
  float scale = 1.0f;             // uniform world scale (stress runs: 1e-3 .. 1e4)
  bool groundUnderFiles = false;  // a floor under a mesh loaded from a file (a receiver for its shadow)
  bool operator==(const SceneNeeds&) const = default;
  // Equal but for sampling: the uploaded textures serve, re-sampled.
  bool sameButSampling(const SceneNeeds& o) const {
    SceneNeeds a = *this;
    a.sampling = o.sampling;
    return a == o;
  }
};

// An image referenced by a material; decoded only on demand.
struct ImageSource {
  std::string name;                  // for messages
  std::filesystem::path file;        // on disk, or
  std::vector<unsigned char> bytes;  // encoded (PNG/JPEG) bytes embedded in a glTF, or
  std::vector<unsigned char> rgba;   // already decoded (procedural), rows top-down
  glm::ivec2 size{0};                // of `rgba`
  gl::SamplerState sampler;
};

struct Material {
  std::string name = "default";
  glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};
  float metallic = 0.0f;
  float roughness = 0.5f;
  int baseColorImage = -1;       // index into Scene::images
  int normalImage = -1;          // tangent space, +Y up the image as displayed (OpenGL convention), unless:
  bool normalGreenDown = false;  // the map's green points down the image (DirectX, Y-): inverted on upload
  int metallicRoughnessImage = -1;
  int heightImage = -1;        // a height field (white = high); its red channel is used
  bool heightIsDepth = false;  // the image stores depth (white = deep): height = 1 - value
};

struct Instance {
  int mesh = 0;
  glm::mat4 model{1.0f};
};

struct Scene {
  std::string name;
  std::vector<MeshData> meshes;
  std::vector<Material> materials{Material{}};
  std::vector<ImageSource> images;
  std::vector<Instance> instances;
  std::vector<std::string> warnings;  // shown in the UI, printed by the CLI
  std::string suggestedCamera;        // OrbitCamera::parse text applied after framing, or ""
  glm::vec3 suggestedLight{0.0f};     // a point the scene's key light shines from, towards the origin; 0: none
  // "lab.key=value" settings the scene is best shown with (the learnopengl scene's cascades): the
  // host applies the current lab's when the scene is picked and counts them as its defaults there.
  std::vector<std::string> suggestedSettings;
  int revision = 0;  // set by the host on every build: caches keyed on it go stale

  Bounds bounds;  // world-space bounds of all instances, kept by the host (computeBounds) after each build
  std::vector<Bounds> instanceBounds;       // each instance's world box, kept beside `bounds`
  Bounds computeBounds() const;             // walks every vertex: call once per build, not per frame
  Bounds boundsOfInstance(size_t i) const;  // its mesh's box through its model matrix
  // Instance indices, nearest box centre (instanceBounds) to `eye` first. Opaque passes draw in this order so that
  // the depth test turns hidden fragments away before they are shaded: a floor drawn after the
  // objects standing on it shades only what they leave visible.
  std::vector<size_t> nearestFirst(glm::vec3 eye) const;
  size_t triangleCount() const;
};

// Decodes an image to RGBA8, rows top-down. Returns "" or a one-line error naming the file.
std::string decodeImage(const ImageSource& source, std::vector<unsigned char>& rgba, glm::ivec2& size);
// Rows top-down (decoded images) to GL's bottom-up order, or back: `channels` bytes per texel.
std::vector<unsigned char> flipRows(const std::vector<unsigned char>& rgba, glm::ivec2 size, int channels);

}  // namespace shadelab
