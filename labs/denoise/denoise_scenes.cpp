#include "labs/denoise/denoise_scenes.h"

#include "app/scene/loaders.h"
#include "app/scene/procedural.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

struct Pair {
  const char* id;
  const char* folder;
  const char* description;
  const char* camera;  // a three-quarter view that shows the model's features
};
const Pair kPairs[] = {
    {"fandisk-0.3", "Fandisk0.3", "Fandisk, CAD part with sharp edges; published noise 0.3 (6,475 v)",
     "yaw=120,pitch=25"},
    {"fandisk-0.7", "Fandisk0.7", "Fandisk with heavy noise 0.7", "yaw=120,pitch=25"},
    {"block-0.4", "Block0.4", "Block, flat faces and sharp edges; noise 0.4 (8,771 v)", "yaw=120,pitch=25"},
    {"sharpsphere-0.3", "SharpSphere0.3", "a sphere with sharp ridges; noise 0.3 (10,443 v)", "yaw=210,pitch=25"},
    {"twelve-0.5-impulsive", "Twelve0.5Impulsive", "Twelve, impulsive noise 0.5 (4,610 v)", "yaw=120,pitch=25"},
    {"nicolo-0.2", "Nicolo0.2", "Nicolo, a scanned statue; noise 0.2 (14,846 v)", "yaw=210,pitch=15"},
    {"bunny-0.2", "Bunny0.2", "the Stanford bunny, open boundary; noise 0.2 (34,834 v)", "yaw=210,pitch=20"},
};

fs::path pairFolder(const Pair& p) { return dataDirectory() / "denoise" / "guided_zhang2015" / p.folder; }

std::string loadFirstMesh(const fs::path& file, Scene& out) {
  Scene s;
  if (auto err = loadObj(file, s); !err.empty()) return err;
  out.meshes = std::move(s.meshes);
  out.instances = std::move(s.instances);
  out.warnings = std::move(s.warnings);
  return {};
}

// A cube of n x n quads per face; each face its own UV chart in a 3 x 2 atlas with margins, so
// every cube edge is a UV seam and a sharp feature at once.
MeshData seamedCube(int n) {
  MeshData m;
  m.name = "seamed cube";
  const MeshData box = makeBox(glm::vec3(1.0f));
  // Every grid point is a point of one integer lattice, (2 q - n) / n per axis, so the copies of a
  // point on an edge shared by two faces have the same bits and weld (computed as o + du s + dv t
  // from each face's corner they differed in the last bit along some edges: a cracked cube).
  const auto lattice = [n](glm::vec3 p) { return glm::ivec3(glm::round((p + 1.0f) * 0.5f * float(n))); };
  for (int face = 0; face < 6; ++face) {
    const uint32_t base = uint32_t(m.positions.size());
    const glm::ivec3 o = lattice(box.positions[size_t(4 * face)]);
    const glm::ivec3 du = (lattice(box.positions[size_t(4 * face + 1)]) - o) / n;
    const glm::ivec3 dv = (lattice(box.positions[size_t(4 * face + 2)]) - o) / n;
    const glm::vec2 chart(float(face % 3) / 3.0f, float(face / 3) / 2.0f);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const glm::ivec3 q = o + du * i + dv * j;
        m.positions.push_back(glm::vec3(2 * q - n) / float(n));
        const float s = float(i) / float(n), t = float(j) / float(n);
        m.uvs.push_back(chart + glm::vec2(0.02f + 0.293f * s, 0.03f + 0.44f * t));
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
        m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
      }
  }
  computeNormals(m);
  return m;
}

// Slivers (a row squeezed to 1e-6 of a cell: angles near 180 degrees, negative cotangents), a
// zero-area face, a flap on an interior edge (non-manifold) and an isolated vertex.
MeshData degenerateMesh() {
  MeshData m = makePlane(2.0f, 12, 1.0f);
  for (size_t v = 0; v < m.positions.size(); ++v)
    if (v / 13 == 6) m.positions[v].z = m.positions[v - 13].z + 1e-6f;  // row 6 onto row 5
  const uint32_t a = 13 * 3 + 3, b = a + 1;                             // an interior edge
  m.positions.push_back(m.positions[a] + glm::vec3(0.1f, 0.5f, 0.0f));
  m.uvs.emplace_back(0.5f, 0.5f);
  m.indices.insert(m.indices.end(), {a, b, uint32_t(m.positions.size() - 1)});
  m.indices.insert(m.indices.end(), {a, a, b});  // zero area
  m.positions.emplace_back(5.0f, 5.0f, 5.0f);    // in no face
  m.uvs.emplace_back(0.0f, 0.0f);
  computeNormals(m);
  m.name = "degenerate";
  return m;
}

void addMesh(Scene& s, MeshData m) {
  s.instances.push_back({int(s.meshes.size()), glm::mat4(1.0f)});
  s.meshes.push_back(std::move(m));
}

}  // namespace

std::vector<SceneRecipe> denoiseScenes() {
  std::vector<SceneRecipe> out;
  std::error_code ec;
  for (auto& p : kPairs)
    if (fs::is_regular_file(pairFolder(p) / "Original.obj", ec))
      out.push_back({p.id, p.description, [folder = pairFolder(p), camera = p.camera](Scene& s, const SceneNeeds&) {
                       s.suggestedCamera = camera;
                       return loadFirstMesh(folder / "Original.obj", s);
                     }});
  out.push_back({"denoise-cube", "a subdivided cube, one UV chart per face: sharp edges and UV seams together",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, seamedCube(24));
                   s.suggestedCamera = "yaw=120,pitch=28";
                   return std::string();
                 }});
  out.push_back({"denoise-sphere-no-uvs", "a sphere without texture coordinates: no map, the attribute path only",
                 [](Scene& s, const SceneNeeds&) {
                   MeshData sphere = makeUvSphere(1.0f, 64);
                   sphere.uvs.clear();
                   addMesh(s, std::move(sphere));
                   return std::string();
                 }});
  out.push_back({"denoise-degenerate", "slivers, a zero-area face, a non-manifold flap, an isolated vertex (stress)",
                 [](Scene& s, const SceneNeeds&) {
                   addMesh(s, degenerateMesh());
                   return std::string();
                 }});
  return out;
}

std::vector<std::string> missingDenoisePairs() {
  std::vector<std::string> out;
  std::error_code ec;
  for (auto& p : kPairs)
    if (!fs::is_regular_file(pairFolder(p) / "Original.obj", ec) ||
        !fs::is_regular_file(pairFolder(p) / "Noisy.obj", ec))
      out.push_back(p.id);
  return out;
}

std::string_view denoiseDefaultScene() {
  std::error_code ec;
  return fs::is_regular_file(pairFolder(kPairs[0]) / "Original.obj", ec) ? kPairs[0].id : "denoise-cube";
}

bool loadPublishedTwin(const std::string& sceneId, MeshData& twin, std::string& error) {
  for (auto& p : kPairs)
    if (sceneId == p.id) {
      Scene s;
      if (auto err = loadFirstMesh(pairFolder(p) / "Noisy.obj", s); !err.empty()) {
        error = err;
        return false;
      }
      twin = std::move(s.meshes.front());
      return true;
    }
  return false;
}

}  // namespace shadelab
