#include "labs/surface/surface_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include "app/scene/loaders.h"
#include "app/scene/procedural.h"
#include "labs/surface/brick_textures.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

// Colour, height and normal map as the scene's images, in one material.
int brickMaterial(Scene& s, BrickTextures t) {
  Material m;
  m.name = "bricks";
  m.baseColor = glm::vec4(1.0f);
  m.baseColorImage = int(s.images.size());
  s.images.push_back(std::move(t.color));
  m.heightImage = int(s.images.size());
  s.images.push_back(std::move(t.height));
  m.normalImage = int(s.images.size());
  s.images.push_back(std::move(t.normal));
  s.materials.push_back(m);
  return int(s.materials.size()) - 1;
}

void addMesh(Scene& s, MeshData mesh, int material, const glm::mat4& model = glm::mat4(1.0f)) {
  mesh.material = material;
  s.instances.push_back({int(s.meshes.size()), model});
  s.meshes.push_back(std::move(mesh));
}

// A wall in the xy plane facing +z, `size` wide, its UVs repeating `repeat` times.
MeshData wall(float size, float repeat) {
  MeshData m = makePlane(size, 1, repeat);
  for (auto& p : m.positions) p = glm::vec3(p.x, -p.z, 0.0f);
  for (auto& n : m.normals) n = glm::vec3(0, 0, 1);
  for (auto& uv : m.uvs) uv.y = repeat - uv.y;  // v runs up the wall
  m.name = "wall";
  return m;
}

}  // namespace

std::vector<SceneRecipe> surfaceScenes() {
  std::vector<SceneRecipe> out;
  out.push_back({"bricks", "a 2 x 2 brick wall with the project's height, normal and colour maps (the default)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, wall(2.0f, 2.0f), brickMaterial(s, makeBrickTextures(512, kBrickDepth)));
                   s.suggestedCamera = "yaw=48,pitch=8,distance=1.6,target=0.3;0;0";  // oblique: depth shows
                   return std::string();
                 }});
  const fs::path lo = dataDirectory() / "textures" / "learnopengl";
  std::error_code ec;
  if (fs::is_regular_file(lo / "bricks2_disp.jpg", ec))
    out.push_back({"bricks-learnopengl", "LearnOpenGL's bricks2 on a 2 x 2 wall (its _disp image is a depth map)",
                   [lo](Scene& s, const SceneNeeds&) {
                     Material m;
                     m.name = "bricks2";
                     m.baseColor = glm::vec4(1.0f);
                     const std::pair<int*, const char*> maps[] = {{&m.baseColorImage, "bricks2.jpg"},
                                                                  {&m.normalImage, "bricks2_normal.jpg"},
                                                                  {&m.heightImage, "bricks2_disp.jpg"}};
                     for (auto& [slot, file] : maps) {
                       ImageSource img;
                       img.name = file;
                       img.file = lo / file;
                       *slot = int(s.images.size());
                       s.images.push_back(img);
                     }
                     m.heightIsDepth = true;  // white is deep: height = 1 - value
                     // Its green points down the image (DirectX, Y-): against the slopes of its own
                     // height field, n.y follows -dh/dy with y running down the rows (test). It was
                     // made for an upload without the row flip, where down the image is +v.
                     m.normalGreenDown = true;
                     s.materials.push_back(m);
                     addMesh(s, wall(2.0f, 1.0f), int(s.materials.size()) - 1);
                     s.suggestedCamera = "yaw=48,pitch=8,distance=1.6,target=0.3;0;0";
                     return std::string();
                   }});
  out.push_back({"bricks-sphere", "bricks on a sphere: curved tangent frames, a UV seam, the poles",
                 [](Scene& s, const SceneNeeds& needs) {
                   MeshData sphere = makeUvSphere(1.0f, std::max(needs.tessellation, 8));
                   for (auto& uv : sphere.uvs) uv *= glm::vec2(4.0f, 2.0f);
                   addMesh(s, std::move(sphere), brickMaterial(s, makeBrickTextures(512, kBrickDepth)));
                   s.suggestedCamera = "yaw=20,pitch=20";
                   return std::string();
                 }});
  out.push_back({"bricks-grazing", "a long brick floor seen at a grazing angle: parallax at its hardest",
                 [](Scene& s, const SceneNeeds&) {
                   MeshData floor = makePlane(1.0f, 1, 1.0f);
                   for (auto& p : floor.positions) p *= glm::vec3(3.0f, 1.0f, 24.0f);
                   for (auto& uv : floor.uvs) uv *= glm::vec2(3.0f, 24.0f);
                   addMesh(s, std::move(floor), brickMaterial(s, makeBrickTextures(512, kBrickDepth)));
                   s.suggestedCamera = "yaw=0,pitch=9,distance=5,target=0;0;7";
                   return std::string();
                 }});
  if (fs::is_regular_file(dataDirectory() / "meshes/spot_pytorch3d/cow.obj", ec))
    out.push_back(
        {"spot-bricks", "Spot wearing the bricks: UV seams and charts of every size", [](Scene& s, const SceneNeeds&) {
           if (auto err = loadObj(dataDirectory() / "meshes/spot_pytorch3d/cow.obj", s); !err.empty()) return err;
           const int material = brickMaterial(s, makeBrickTextures(512, kBrickDepth));
           for (auto& m : s.meshes) {
             m.material = material;
             for (auto& uv : m.uvs) uv *= 6.0f;  // Spot's charts are small: bricks of a readable size
           }
           s.suggestedCamera = "yaw=210,pitch=15,distance=2.8";  // the lit side of the face
           return std::string();
         }});
  // Stress scenes: maps and meshes that break what is not written with care.
  out.push_back({"spike", "a flat wall whose height map is one spike: the steepest slope an 8-bit map can hold",
                 [](Scene& s, const SceneNeeds&) {
                   BrickTextures t = makeBrickTextures(64, kBrickDepth);
                   for (size_t i = 0; i < t.height.rgba.size(); i += 4)
                     t.height.rgba[i] = t.height.rgba[i + 1] = t.height.rgba[i + 2] = 0;
                   for (int y = 31; y <= 32; ++y)
                     for (int x = 31; x <= 32; ++x)
                       for (int c = 0; c < 3; ++c) t.height.rgba[(size_t(y) * 64 + size_t(x)) * 4 + size_t(c)] = 255;
                   t.normal = normalMapFromHeight(t.height, kBrickDepth);
                   addMesh(s, wall(2.0f, 1.0f), brickMaterial(s, std::move(t)));
                   return std::string();
                 }});
  out.push_back(
      {"broken-maps", "a wall whose normal map holds zero-length and non-unit texels", [](Scene& s, const SceneNeeds&) {
         BrickTextures t = makeBrickTextures(128, kBrickDepth);
         for (size_t i = 0; i < t.normal.rgba.size(); i += 4) {
           const size_t texel = i / 4, x = texel % 128;
           if (x < 43)
             t.normal.rgba[i] = t.normal.rgba[i + 1] = t.normal.rgba[i + 2] = 128;  // ~ (0, 0, 0)
           else if (x < 86)
             t.normal.rgba[i] = t.normal.rgba[i + 1] = t.normal.rgba[i + 2] = 0;  // (-1, -1, -1)
         }
         addMesh(s, wall(2.0f, 2.0f), brickMaterial(s, std::move(t)));
         return std::string();
       }});
  out.push_back({"uv-trouble", "a strip whose UVs mirror at the middle and collapse to a point along one row",
                 [](Scene& s, const SceneNeeds&) {
                   MeshData m = makePlane(2.0f, 8, 1.0f);
                   for (size_t v = 0; v < m.positions.size(); ++v) {
                     m.uvs[v].x = std::abs(m.uvs[v].x - 0.5f) * 2.0f;     // mirrored about x = 0
                     if (v / 9 == 2) m.uvs[v] = glm::vec2(0.25f, 0.25f);  // one row: zero-area in UV
                   }
                   addMesh(s, std::move(m), brickMaterial(s, makeBrickTextures(256, kBrickDepth)));
                   s.suggestedCamera = "yaw=20,pitch=40";
                   return std::string();
                 }});
  out.push_back({"no-uvs", "a sphere without texture coordinates: nothing to map", [](Scene& s, const SceneNeeds&) {
                   MeshData sphere = makeUvSphere(1.0f, 48);
                   sphere.uvs.clear();
                   addMesh(s, std::move(sphere), brickMaterial(s, makeBrickTextures(64, kBrickDepth)));
                   return std::string();
                 }});
  return out;
}

}  // namespace shadelab
