#include "app/scene/scene_catalog.h"

#include <cmath>
#include <cstdlib>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "app/scene/camera.h"
#include "app/scene/loaders.h"
#include "app/scene/procedural.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

void add(Scene& s, MeshData mesh, const glm::mat4& model, int material = 0) {
  mesh.material = material;
  s.instances.push_back({int(s.meshes.size()), model});
  s.meshes.push_back(std::move(mesh));
}

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

int addMaterial(Scene& s, const char* name, glm::vec3 color, int image = -1) {
  Material m;
  m.name = name;
  m.baseColor = glm::vec4(color, 1.0f);
  m.baseColorImage = image;
  s.materials.push_back(m);
  return int(s.materials.size()) - 1;
}

// A floor whose two big triangles make affine UV interpolation visibly wrong.
int checkerFloor(Scene& s) {
  s.images.push_back(makeCheckerImage(512, 8));
  return addMaterial(s, "checker", glm::vec3(0.8f), int(s.images.size()) - 1);
}

struct Builder {
  const char* id;
  const char* description;
  std::function<void(Scene&, int tessellation)> build;
};

const std::vector<Builder>& builders() {
  static const std::vector<Builder> list = {
      {"shading", "sphere and torus over a two-triangle checker floor (the shading lab's default)",
       [](Scene& s, int seg) {
         const int floor = checkerFloor(s);
         add(s, makePlane(6.0f, 1, 1.5f), glm::mat4(1.0f), floor);
         add(s, makeUvSphere(1.0f, seg), at(-1.3f, 1.0f, 0.0f), addMaterial(s, "red", {0.8f, 0.25f, 0.2f}));
         add(s, makeTorus(0.75f, 0.3f, seg), glm::rotate(at(1.4f, 1.0f, 0.0f), 1.2f, {1, 0, 0}),
             addMaterial(s, "blue", {0.25f, 0.4f, 0.85f}));
         s.suggestedCamera = "yaw=20,pitch=24,distance=7.2,target=0;0.7;0";  // the objects, with the floor receding
       }},
      {"sphere", "one UV sphere", [](Scene& s, int seg) { add(s, makeUvSphere(1.0f, seg), glm::mat4(1.0f)); }},
      {"torus", "one torus", [](Scene& s, int seg) { add(s, makeTorus(1.0f, 0.4f, seg), glm::mat4(1.0f)); }},
      {"cube", "one unit cube", [](Scene& s, int) { add(s, makeBox(glm::vec3(0.5f)), glm::mat4(1.0f)); }},
      {"checker-plane", "a two-triangle checker floor alone (perspective-correct vs affine UVs)",
       [](Scene& s, int) {
         add(s, makePlane(6.0f, 1, 1.5f), glm::mat4(1.0f), checkerFloor(s));
         s.suggestedCamera = "yaw=30,pitch=22,distance=6.5";
       }},
      {"shadow-test", "ground, four pillars, a torus and a sphere (grazing, acne-prone surfaces)",
       [](Scene& s, int seg) {
         add(s, makePlane(12.0f, 1, 6.0f), glm::mat4(1.0f), addMaterial(s, "ground", {0.75f, 0.75f, 0.7f}));
         const int stone = addMaterial(s, "stone", {0.7f, 0.65f, 0.55f});
         for (int i = 0; i < 4; ++i) add(s, makeBox({0.25f, 1.25f, 0.25f}), at(-3.0f + 2.0f * i, 1.25f, -2.5f), stone);
         add(s, makeTorus(0.8f, 0.25f, seg), glm::rotate(at(1.2f, 0.9f, 0.8f), 1.0f, {1, 0, 0}),
             addMaterial(s, "blue", {0.25f, 0.4f, 0.85f}));
         add(s, makeUvSphere(0.7f, seg), at(-1.3f, 0.7f, 0.9f), addMaterial(s, "red", {0.8f, 0.25f, 0.2f}));
         s.suggestedCamera = "yaw=15,pitch=30,distance=11,target=0;0.6;0";
         // The camera sees most of the ground, but not its far corners: a map fitted to the view
         // misclassifies 0.042 % of the pixels against ray-traced visibility, one fitted to the
         // whole scene 0.053 % (hard shadows, 800x600; bench BM_DefaultFit).
         s.suggestedSettings = {"shadows.fit=view"};
       }},
      {"empty", "nothing at all (stress runs: a lab must cope)", [](Scene&, int) {}},
  };
  return list;
}

struct DataScene {
  const char* id;
  const char* relPath;
  const char* description;
  bool ground;         // put a floor under it (a receiver for shadows)
  const char* camera;  // yaw and pitch of a view that shows its front, or ""
};
const DataScene kDataScenes[] = {
    {"spot", "meshes/spot_pytorch3d/cow.obj", "Keenan Crane's Spot cow, textured (shared data)", false,
     "yaw=150,pitch=15"},
    {"teapot", "meshes/teapot_pytorch3d/teapot.obj", "the Utah teapot (shared data)", false, ""},
    {"spot-on-plane", "meshes/spot_pytorch3d/cow.obj", "Spot standing on a floor (shared data)", true,
     "yaw=150,pitch=22"},
    {"teapot-on-plane", "meshes/teapot_pytorch3d/teapot.obj", "the teapot on a floor (shared data)", true, ""},
};

// A floor four bounding radii wide, touching the lowest point of what is there.
void addGround(Scene& s) {
  const Bounds b = s.computeBounds();
  add(s, makePlane(4.0f * b.radius(), 1, 4.0f), at(b.center().x, b.min.y, b.center().z),
      addMaterial(s, "ground", {0.75f, 0.75f, 0.7f}));
}

}  // namespace

fs::path dataDirectory() {
  if (const char* env = std::getenv("SHADELAB_DATA"); env && *env) return fs::path(env);
  std::error_code ec;
  const fs::path beside = fs::path(SHADELAB_SOURCE_DIR).parent_path() / "shared" / "data";
  if (fs::is_directory(beside, ec)) return beside;
  const fs::path fetched = fs::path(SHADELAB_SOURCE_DIR) / "data";
  return fs::is_directory(fetched, ec) ? fetched : fs::path();
}

std::vector<std::string> missingDataScenes() {
  const fs::path data = dataDirectory();
  std::vector<std::string> out;
  std::error_code ec;
  for (auto& d : kDataScenes)
    if (data.empty() || !fs::is_regular_file(data / d.relPath, ec)) out.push_back(d.id);
  return out;
}

std::vector<SceneEntry> listScenes(std::span<const SceneRecipe> labScenes) {
  std::vector<SceneEntry> out;
  for (auto& r : labScenes) out.push_back({r.id, r.description});
  for (auto& b : builders()) out.push_back({b.id, b.description});
  const fs::path data = dataDirectory();
  std::error_code ec;
  for (auto& d : kDataScenes)
    if (!data.empty() && fs::is_regular_file(data / d.relPath, ec)) out.push_back({d.id, d.description});
  return out;
}

std::string buildScene(const std::string& idOrPath, const SceneNeeds& needs, Scene& out,
                       std::span<const SceneRecipe> labScenes) {
  out = Scene{};
  out.name = idOrPath;
  bool found = false;
  for (auto& r : labScenes)
    if (!found && idOrPath == r.id) {
      if (auto err = r.build(out, needs); !err.empty()) return err;
      found = true;
    }
  for (auto& b : builders())
    if (!found && idOrPath == b.id) {
      b.build(out, needs.tessellation);
      found = true;
    }
  if (!found) {
    fs::path file = idOrPath;
    bool ground = false;
    const char* camera = "";
    for (auto& d : kDataScenes)
      if (idOrPath == d.id) {
        if (std::error_code ec; !fs::is_regular_file(dataDirectory() / d.relPath, ec))
          return "scene '" + idOrPath + "' needs " + d.relPath + ", which is not here: " + kGetDataCommand +
                 " fetches it (or set SHADELAB_DATA to a folder that has it)";
        file = dataDirectory() / d.relPath;
        ground = d.ground;
        camera = d.camera;
      }
    const bool looksLikeFile = file.has_extension() || file.string().find('/') != std::string::npos;
    if (!looksLikeFile) {
      std::string valid;
      for (auto& e : listScenes(labScenes)) valid += (valid.empty() ? "" : ", ") + e.id;
      return "unknown scene '" + idOrPath + "' (valid: " + valid + ", or a .gltf/.glb/.obj/.off/.ply file)";
    }
    if (auto err = loadSceneFile(file, out); !err.empty()) return err;
    if (ground || needs.groundUnderFiles) addGround(out);
    if (needs.groundUnderFiles && out.suggestedLight == glm::vec3(0.0f)) {
      // A light that shows the mesh's shadow on the floor from the default view: from the camera's
      // left, a little behind the mesh and 45 degrees up, so the shadow falls forward and right,
      // in view (from behind the camera it would hide behind the mesh).
      const float yaw = glm::radians(OrbitCamera{}.yawDeg);
      const glm::vec3 toCamera(std::sin(yaw), 0.0f, std::cos(yaw)), right(std::cos(yaw), 0.0f, -std::sin(yaw));
      const glm::vec3 across = glm::normalize(-right - 0.5f * toCamera);
      out.suggestedLight = across + glm::vec3(0.0f, 1.0f, 0.0f);  // 45 degrees above the horizon
    }
    out.name = idOrPath;
    out.suggestedCamera = camera;
  }
  if (needs.scale != 1.0f) {
    for (auto& inst : out.instances) inst.model = glm::scale(glm::mat4(1.0f), glm::vec3(needs.scale)) * inst.model;
    out.suggestedCamera.clear();  // it is in unscaled units; framing the bounds still works
  }
  out.instanceBounds.clear();
  for (size_t i = 0; i < out.instances.size(); ++i) out.instanceBounds.push_back(out.boundsOfInstance(i));
  out.bounds = out.computeBounds();
  // Leave out what the configuration does not use.
  for (auto& mesh : out.meshes) {
    if (!needs.uvs) mesh.uvs.clear();
    if (needs.tangents && !mesh.uvs.empty()) {
      if (int n = computeTangents(mesh).fallbacks; n > 0)
        out.warnings.push_back("mesh '" + mesh.name + "': " + std::to_string(n) +
                               " vertices have degenerate UVs; their tangent is an arbitrary perpendicular");
    }
  }
  return {};
}

}  // namespace shadelab
