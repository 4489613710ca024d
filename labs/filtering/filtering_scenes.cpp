#include "labs/filtering/filtering_scenes.h"

#include <algorithm>
#include <cmath>

#include "app/scene/loaders.h"
#include "app/scene/procedural.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

ImageSource blank(std::string name, glm::ivec2 size) {
  ImageSource img;
  img.name = std::move(name);
  img.size = size;
  img.rgba.assign(size_t(size.x) * size_t(size.y) * 4, 255);
  return img;
}

void put(ImageSource& img, int x, int y, glm::vec3 srgb) {
  uint8_t* p = &img.rgba[(size_t(y) * size_t(img.size.x) + size_t(x)) * 4];
  for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(std::clamp(srgb[c], 0.0f, 1.0f) * 255.0f));
}

int texturedMaterial(Scene& s, ImageSource image) {
  Material m;
  m.name = image.name;
  m.baseColor = glm::vec4(1.0f);
  m.baseColorImage = int(s.images.size());
  s.images.push_back(std::move(image));
  s.materials.push_back(m);
  return int(s.materials.size()) - 1;
}

void addMesh(Scene& s, MeshData mesh, int material) {
  mesh.material = material;
  s.instances.push_back({int(s.meshes.size()), glm::mat4(1.0f)});
  s.meshes.push_back(std::move(mesh));
}

// A ground plane (y = 0) `width` x `length`, from z = +2 to z = 2 - length, `tilesPerUnit`
// texture repeats per world unit.
MeshData ground(float width, float length, float repeatsPerUnit) {
  MeshData m = makePlane(1.0f, 1, 1.0f);
  for (auto& p : m.positions) p = glm::vec3(p.x * width, 0.0f, 2.0f - (p.z + 0.5f) * length);
  for (auto& uv : m.uvs) uv *= glm::vec2(width, length) * repeatsPerUnit;
  m.name = "ground";
  return m;
}

// A square facing +z, UVs 0..1 once.
MeshData quad(float size) {
  MeshData m = makePlane(size, 1, 1.0f);
  for (auto& p : m.positions) p = glm::vec3(p.x, -p.z, 0.0f);
  for (auto& n : m.normals) n = glm::vec3(0, 0, 1);
  for (auto& uv : m.uvs) uv.y = 1.0f - uv.y;  // v runs up
  m.name = "quad";
  return m;
}

constexpr const char* kGrazingCamera = "yaw=0,pitch=12,distance=6,target=0;0;-5";

}  // namespace

ImageSource makeTileImage(int size, int tiles) {
  ImageSource img = blank("procedural tiles", {size, size});
  const int cell = std::max(size / tiles, 1);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const bool line = x % cell == 0 || y % cell == 0;  // one texel wide: the finest detail there is
      const bool white = ((x / cell + y / cell) & 1) != 0;
      put(img, x, y, line ? glm::vec3(0.85f, 0.15f, 0.1f) : glm::vec3(white ? 0.92f : 0.12f));
    }
  return img;
}

ImageSource makeZonePlateImage(glm::ivec2 size) {
  ImageSource img = blank("procedural zone plate", size);
  const float n = float(std::max(size.x, size.y));
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float dx = x + 0.5f - 0.5f * size.x, dy = y + 0.5f - 0.5f * size.y;
      // Local frequency r / n cycles per texel: 0.5 (Nyquist) half the larger side from the centre.
      const float v = 0.5f + 0.5f * std::cos(float(M_PI) * (dx * dx + dy * dy) / n);
      put(img, x, y, glm::vec3(v, v * 0.9f + 0.05f, 0.3f + 0.6f * v));
    }
  return img;
}

ImageSource makePixelArtImage() {
  ImageSource img = blank("procedural pixel art", {16, 16});
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      glm::vec3 c(0.95f, 0.93f, 0.85f);
      const float r = std::hypot(x - 7.5f, y - 7.5f);
      if (r > 4.5f && r < 6.0f) c = {0.95f, 0.55f, 0.1f};                      // a ring
      if (x == y) c = {0.1f, 0.3f, 0.85f};                                     // a diagonal
      if ((x == 3 || x == 12) && (y == 3 || y == 12)) c = {0.1f, 0.6f, 0.2f};  // four dots
      if (x == 0 || y == 0 || x == 15 || y == 15) c = glm::vec3(0.15f);        // a frame
      put(img, x, y, c);
    }
  return img;
}

ImageSource makeSolidImage(glm::vec4 srgb) {
  ImageSource img = blank("one texel", {1, 1});
  put(img, 0, 0, glm::vec3(srgb));
  return img;
}

std::vector<SceneRecipe> filteringScenes() {
  std::vector<SceneRecipe> out;
  out.push_back({"grazing-tiles", "tiles on a 20 x 200 ground plane seen at a grazing angle (the default)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, ground(20.0f, 200.0f, 0.5f), texturedMaterial(s, makeTileImage(512, 8)));
                   s.suggestedCamera = kGrazingCamera;
                   return std::string();
                 }});
  out.push_back({"grazing-zoneplate", "a zone plate on the same ground plane: every frequency, every distance",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, ground(20.0f, 200.0f, 0.25f), texturedMaterial(s, makeZonePlateImage({512, 512})));
                   s.suggestedCamera = kGrazingCamera;
                   return std::string();
                 }});
  out.push_back({"zoneplate",
                 "a zone plate facing the camera, a little smaller than its texels (minification "
                 "without perspective)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, quad(2.0f), texturedMaterial(s, makeZonePlateImage({1024, 1024})));
                   s.suggestedCamera = "yaw=0,pitch=0,distance=2.5,target=0;0;0";
                   return std::string();
                 }});
  out.push_back({"magnify", "a 16 x 16 texture filling the screen: magnification, texels tens of pixels wide",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, quad(2.0f), texturedMaterial(s, makePixelArtImage()));
                   s.suggestedCamera = "yaw=0,pitch=0,distance=2.7,target=0;0;0";
                   return std::string();
                 }});
  std::error_code ec;
  const fs::path spot = dataDirectory() / "meshes/spot_pytorch3d/cow.obj";
  if (fs::is_regular_file(spot, ec))
    out.push_back(
        {"spot", "Spot with its own 1024 x 1024 texture (../shared/data)", [spot](Scene& s, const SceneNeeds&) {
           if (auto err = loadObj(spot, s); !err.empty()) return err;
           s.suggestedCamera = "yaw=210,pitch=15,distance=2.8";
           return std::string();
         }});
  // Stress scenes.
  out.push_back(
      {"horizon", "a 20 x 4000 plane to the horizon: thousands of texels per pixel", [](Scene& s, const SceneNeeds&) {
         addMesh(s, ground(20.0f, 4000.0f, 0.5f), texturedMaterial(s, makeTileImage(512, 8)));
         s.suggestedCamera = "yaw=0,pitch=1,distance=6,target=0;0.2;-4";
         return std::string();
       }});
  out.push_back({"npot",
                 "a 300 x 200 zone plate on the grazing plane: a mip chain of odd sizes (150 x 100, 75 x 50, "
                 "37 x 25, ...)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, ground(20.0f, 200.0f, 0.25f), texturedMaterial(s, makeZonePlateImage({300, 200})));
                   s.suggestedCamera = kGrazingCamera;
                   return std::string();
                 }});
  out.push_back(
      {"one-texel", "a 1 x 1 texture on the grazing plane: one level, nothing to filter",
       [](Scene& s, const SceneNeeds&) {
         addMesh(s, ground(20.0f, 200.0f, 0.5f), texturedMaterial(s, makeSolidImage({0.9f, 0.5f, 0.2f, 1.0f})));
         s.suggestedCamera = kGrazingCamera;
         return std::string();
       }});
  out.push_back({"constant-uv",
                 "a quad whose four corners share one texture coordinate: zero derivatives, L = "
                 "log2(0)",
                 [](Scene& s, const SceneNeeds&) {
                   MeshData m = quad(2.0f);
                   for (auto& uv : m.uvs) uv = glm::vec2(0.3f, 0.6f);
                   addMesh(s, std::move(m), texturedMaterial(s, makeTileImage(256, 8)));
                   s.suggestedCamera = "yaw=0,pitch=0,distance=3,target=0;0;0";
                   return std::string();
                 }});
  out.push_back({"huge-uv",
                 "the grazing plane with texture coordinates up to 10^6: millions of texels per pixel and "
                 "float precision running out",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, ground(20.0f, 200.0f, 5000.0f), texturedMaterial(s, makeTileImage(512, 8)));
                   s.suggestedCamera = kGrazingCamera;
                   return std::string();
                 }});
  out.push_back({"unused-texture",
                 "a plane with one texture and a second image no material uses (it must never be "
                 "decoded)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, quad(2.0f), texturedMaterial(s, makeTileImage(64, 4)));
                   ImageSource unused;
                   unused.name = "unused.png";
                   unused.file = "/nonexistent/unused.png";  // decoding it would fail loudly
                   s.images.push_back(unused);
                   s.suggestedCamera = "yaw=0,pitch=0,distance=3,target=0;0;0";
                   return std::string();
                 }});
  return out;
}

}  // namespace shadelab
