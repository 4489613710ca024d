#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "app/scene/loaders.h"
#include "app/util/contained_path.h"

namespace fs = std::filesystem;

namespace shadelab {

static std::string firstLine(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  const auto nl = s.find('\n');
  return nl == std::string::npos ? s : s.substr(0, nl) + " (and more)";
}

namespace {

// A height field is grey; a tangent-space normal map is blue-violet. True when at most 1% of the
// texels have channels more than 12 of 255 apart (JPEG leaves some chroma on grey pictures).
// An image that cannot be decoded is not called grey (the loader's warnings name it).
bool isGreyImage(const ImageSource& image) {
  std::vector<unsigned char> rgba;
  glm::ivec2 size;
  if (image.file.empty() || !decodeImage(image, rgba, size).empty()) return false;
  size_t coloured = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    const int r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
    coloured += std::max({r, g, b}) - std::min({r, g, b}) > 12;
  }
  return coloured * 100 <= rgba.size() / 4;
}

// `name` (an MTL library or a texture) as a file beside the OBJ; empty, with a warning, when the
// name leaves the OBJ's folder or is not a regular file there (an OBJ from the web cannot make
// ShadeLab read /etc/passwd, a neighbour's folder or /dev/zero).
fs::path besideModel(const fs::path& folder, const std::string& name, std::string& warnings) {
  const fs::path rel = containedName(name);
  const fs::path file = rel.empty() ? fs::path() : folder / rel;
  std::error_code ec;
  if (!file.empty() && !fs::exists(file, ec)) return file;  // missing: reported where it is used
  if (file.empty() || !fs::is_regular_file(file, ec) || !realPathInside(folder, file)) {
    warnings += "'" + name + "' is not a file in the OBJ's folder; not read\n";
    return {};
  }
  return file;
}

// MTL libraries, read only from the OBJ's folder.
class FolderMaterialReader final : public tinyobj::MaterialReader {
 public:
  explicit FolderMaterialReader(fs::path folder) : folder_(std::move(folder)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warn, std::string* err) override {
    const fs::path file = besideModel(folder_, name, *warn);
    std::ifstream in(file);
    if (file.empty() || !in) {
      if (!file.empty()) *warn += "material library '" + name + "' not found\n";
      return false;
    }
    tinyobj::LoadMtl(names, materials, &in, warn, err);
    return true;
  }

 private:
  fs::path folder_;
};

}  // namespace

std::string loadObj(const fs::path& file, Scene& scene) {
  if (std::error_code ec; !fs::is_regular_file(file, ec)) return file.string() + ": no such file";
  const fs::path folder = fs::absolute(file).parent_path();
  std::ifstream in(file);
  if (!in) return file.string() + ": cannot open";
  FolderMaterialReader mtl(folder);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &mtl, /*triangulate=*/true,
                        /*default_vcols_fallback=*/false))
    return file.string() + ": " + firstLine(err.empty() ? "not a valid OBJ file" : err);

  // Materials: MTL diffuse colour and map_Kd (recorded, decoded later on demand).
  const int materialBase = int(scene.materials.size());
  for (auto& m : materials) {
    Material mat;
    mat.name = m.name;
    mat.baseColor = glm::vec4(m.diffuse[0], m.diffuse[1], m.diffuse[2], 1.0f);
    if (!m.diffuse_texname.empty()) {
      ImageSource img;
      img.name = m.diffuse_texname;
      img.file = besideModel(folder, m.diffuse_texname, warn);
      mat.baseColorImage = int(scene.images.size());
      scene.images.push_back(img);
    }
    // A height field from `disp`; `bump` is one too by the MTL spec, but many exporters write their
    // normal maps there: with a `norm` map beside it, or grey texels, it is read as a height field.
    auto add = [&](const std::string& name) {
      ImageSource img;
      img.name = name;
      img.file = besideModel(folder, name, warn);
      scene.images.push_back(img);
      return int(scene.images.size()) - 1;
    };
    if (!m.displacement_texname.empty()) mat.heightImage = add(m.displacement_texname);
    if (!m.normal_texname.empty()) mat.normalImage = add(m.normal_texname);
    if (!m.bump_texname.empty()) {
      const int bump = add(m.bump_texname);
      const bool height = !m.normal_texname.empty() || isGreyImage(scene.images[size_t(bump)]);
      if (height && mat.heightImage < 0)
        mat.heightImage = bump;
      else if (!height)
        mat.normalImage = bump;
    }
    scene.materials.push_back(mat);
  }
  if (!warn.empty()) scene.warnings.push_back(file.string() + ": " + firstLine(warn));

  // OBJ indexes positions, normals and UVs separately; GL wants one index per vertex, so each
  // distinct (v, vt, vn) triple becomes one vertex. UV seams split vertices, as they must.
  size_t skipped = 0;
  for (auto& shape : shapes) {
    MeshData mesh;
    mesh.name = shape.name.empty() ? file.stem().string() : shape.name;
    const int mid = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids.front();
    mesh.material = mid >= 0 ? materialBase + mid : 0;
    std::map<std::tuple<int, int, int>, uint32_t> remap;
    const bool hasNormals = !attrib.normals.empty(), hasUvs = !attrib.texcoords.empty();
    const int vertices = int(attrib.vertices.size() / 3), normals = int(attrib.normals.size() / 3),
              texcoords = int(attrib.texcoords.size() / 2);
    // tinyobjloader warns about indices past the data but hands them over: check every one, and
    // skip the triangles that have any (they would read past the arrays).
    auto valid = [&](const tinyobj::index_t& i) {
      return i.vertex_index >= 0 && i.vertex_index < vertices && i.normal_index < normals &&
             i.texcoord_index < texcoords;
    };
    const auto& indices = shape.mesh.indices;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      if (!valid(indices[t]) || !valid(indices[t + 1]) || !valid(indices[t + 2])) {
        ++skipped;
        continue;
      }
      for (size_t k = t; k < t + 3; ++k) {
        const tinyobj::index_t& idx = indices[k];
        const auto key =
            std::make_tuple(idx.vertex_index, hasNormals ? idx.normal_index : -1, hasUvs ? idx.texcoord_index : -1);
        auto [it, added] = remap.emplace(key, uint32_t(mesh.positions.size()));
        if (added) {
          const float* p = &attrib.vertices[size_t(3 * idx.vertex_index)];
          mesh.positions.emplace_back(p[0], p[1], p[2]);
          mesh.sourceVertex.push_back(uint32_t(idx.vertex_index));
          if (hasNormals && idx.normal_index >= 0) {
            const float* n = &attrib.normals[size_t(3 * idx.normal_index)];
            mesh.normals.emplace_back(n[0], n[1], n[2]);
          } else if (hasNormals) {
            mesh.normals.emplace_back(0, 0, 0);
          }
          if (hasUvs && idx.texcoord_index >= 0) {
            const float* uv = &attrib.texcoords[size_t(2 * idx.texcoord_index)];
            mesh.uvs.emplace_back(uv[0], uv[1]);
          } else if (hasUvs) {
            mesh.uvs.emplace_back(0, 0);
          }
        }
        mesh.indices.push_back(it->second);
      }
    }
    if (mesh.indices.empty()) continue;
    if (auto err = validateMesh(mesh); !err.empty()) return file.string() + ": " + err;
    if (mesh.normals.empty()) computeNormals(mesh);
    scene.instances.push_back({int(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(mesh));
  }
  const std::string dropped = std::to_string(skipped) + " triangle(s) index past the vertex data";
  if (scene.meshes.empty()) return file.string() + ": no valid triangle (" + (skipped ? dropped : "no faces") + ")";
  if (skipped) scene.warnings.push_back(file.string() + ": " + dropped + " and were left out");
  return {};
}

// OFF: "OFF", then "V F E", then V lines of x y z, then F lines of "n i0 i1 ... i(n-1)".
std::string loadOff(const fs::path& file, Scene& scene) {
  std::ifstream in(file);
  if (!in) return file.string() + ": no such file";
  auto nextLine = [&](std::string& line) {
    while (std::getline(in, line)) {
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
    }
    return false;
  };
  std::string line;
  if (!nextLine(line) || line.rfind("OFF", 0) != 0) return file.string() + ": not an OFF file (first line must be OFF)";
  std::istringstream rest(line.substr(3));
  long v = -1, f = -1;
  if (!(rest >> v >> f)) {
    if (!nextLine(line)) return file.string() + ": missing vertex/face counts";
    std::istringstream counts(line);
    counts >> v >> f;
  }
  if (v <= 0 || f <= 0 || v > 50'000'000 || f > 100'000'000)
    return file.string() + ": bad vertex/face counts (" + std::to_string(v) + ", " + std::to_string(f) + ")";
  MeshData mesh;
  mesh.name = file.stem().string();
  for (long i = 0; i < v; ++i) {
    glm::vec3 p;
    if (!nextLine(line) || !(std::istringstream(line) >> p.x >> p.y >> p.z))
      return file.string() + ": vertex " + std::to_string(i) + " is missing or malformed";
    mesh.positions.push_back(p);
  }
  for (long i = 0; i < f; ++i) {
    std::istringstream face;
    int n = 0;
    if (nextLine(line)) face.str(line);
    if (!(face >> n) || n < 3 || n > 65536)
      return file.string() + ": face " + std::to_string(i) + " is missing or malformed";
    std::vector<uint32_t> poly(static_cast<size_t>(n));
    for (auto& idx : poly)
      if (!(face >> idx)) return file.string() + ": face " + std::to_string(i) + " has too few indices";
    for (int k = 1; k + 1 < n; ++k)
      mesh.indices.insert(mesh.indices.end(), {poly[0], poly[size_t(k)], poly[size_t(k) + 1]});
  }
  if (auto err = validateMesh(mesh); !err.empty()) return file.string() + ": " + err;
  computeNormals(mesh);
  scene.instances.push_back({int(scene.meshes.size()), glm::mat4(1.0f)});
  scene.meshes.push_back(std::move(mesh));
  return {};
}

std::string loadSceneFile(const fs::path& file, Scene& scene) {
  std::string ext = file.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  scene.name = file.filename().string();
  std::string err;
  if (ext == ".gltf" || ext == ".glb")
    err = loadGltf(file, scene);
  else if (ext == ".obj")
    err = loadObj(file, scene);
  else if (ext == ".off")
    err = loadOff(file, scene);
  else if (ext == ".ply")
    err = loadPly(file, scene);
  else
    return file.string() + ": unknown scene file type '" + ext + "' (valid: .gltf, .glb, .obj, .off, .ply)";
  if (!err.empty()) return err;
  // A loader may skip what it cannot use (faces indexing past the vertices): nothing left is an
  // error, not an empty frame.
  if (scene.triangleCount() == 0)
    return file.string() + ": no valid triangle" + (scene.warnings.empty() ? "" : " (" + scene.warnings.back() + ")");
  return {};
}

}  // namespace shadelab
