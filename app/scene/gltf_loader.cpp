// glTF 2.0 through Debian's libtinygltf. Node transforms are flattened into instances; images
// are kept encoded (our image callback stores the bytes) until a lab needs them.
#include <tiny_gltf.h>

#include <cstring>
#include <limits>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/scene/loaders.h"
#include "app/util/contained_path.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

bool keepEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                 int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = -1;  // marks "still encoded"
  return true;
}

// Reads component `c` of element `i` as float (normalised integers map to [0,1] / [-1,1]).
float readComponent(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      auto v = float(int8_t(*p));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return float(v);
    }
    default:
      return 0.0f;
  }
}

// All elements of an accessor as floats, `comps` per element; "" or an error.
std::string readAccessor(const tinygltf::Model& m, int index, int comps, std::vector<float>& out) {
  if (index < 0 || size_t(index) >= m.accessors.size()) return "accessor " + std::to_string(index) + " does not exist";
  const auto& acc = m.accessors[size_t(index)];
  if (acc.bufferView < 0 || size_t(acc.bufferView) >= m.bufferViews.size()) return "accessor without buffer view";
  const auto& view = m.bufferViews[size_t(acc.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
    return "buffer view " + std::to_string(acc.bufferView) + " names no buffer";
  const auto& buffer = m.buffers[size_t(view.buffer)];
  const int compSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
  const int stride = acc.ByteStride(view);
  if (compSize <= 0 || stride <= 0) return "accessor " + std::to_string(index) + " has a bad component type";
  // Every bound checked without overflow: offsets and counts come from the file.
  const size_t bytes = buffer.data.size(), element = size_t(compSize * comps);
  const size_t start = view.byteOffset + acc.byteOffset;
  const bool fits =
      view.byteOffset <= bytes && acc.byteOffset <= bytes - view.byteOffset &&
      (acc.count == 0 || (element <= bytes - start && (acc.count - 1) <= (bytes - start - element) / size_t(stride)));
  if (!fits) return "accessor " + std::to_string(index) + " reads past the end of its buffer";
  out.resize(acc.count * size_t(comps));
  for (size_t i = 0; i < acc.count; ++i)
    for (int c = 0; c < comps; ++c)
      out[i * size_t(comps) + size_t(c)] = readComponent(
          &buffer.data[start + i * size_t(stride) + size_t(c * compSize)], acc.componentType, acc.normalized);
  return {};
}

GLenum wrapMode(int w) {
  return w == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? GL_CLAMP_TO_EDGE
         : w == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? GL_MIRRORED_REPEAT
                                                      : GL_REPEAT;
}

glm::mat4 nodeTransform(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::dmat4 m = glm::make_mat4(n.matrix.data());
    return glm::mat4(m);
  }
  glm::mat4 t(1.0f);
  if (n.translation.size() == 3) t = glm::translate(t, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4)
    t *= glm::mat4_cast(
        glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
  if (n.scale.size() == 3) t = glm::scale(t, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
  return t;
}

struct Importer {
  const tinygltf::Model& model;
  Scene& scene;
  std::vector<std::vector<int>> meshPrimitives;  // glTF mesh -> our mesh indices
  int materialBase = 0;
  std::map<std::pair<int, int>, int> images;  // (glTF image, glTF sampler) -> our image

  // glTF puts the sampler on the texture, not the image: each (image, sampler) pair becomes one
  // ImageSource, so two textures that share an image but not a sampler both keep their wrap modes.
  int image(int textureIndex) {
    if (textureIndex < 0 || size_t(textureIndex) >= model.textures.size()) return -1;
    const auto& tex = model.textures[size_t(textureIndex)];
    if (tex.source < 0 || size_t(tex.source) >= model.images.size()) return -1;
    const int sampler = tex.sampler >= 0 && size_t(tex.sampler) < model.samplers.size() ? tex.sampler : -1;
    if (auto it = images.find({tex.source, sampler}); it != images.end()) return it->second;
    const auto& gltfImage = model.images[size_t(tex.source)];
    ImageSource img;
    img.name = gltfImage.uri.empty() ? gltfImage.name : gltfImage.uri;
    img.bytes = gltfImage.image;  // still encoded: decoded only if a lab needs it
    if (sampler >= 0) {
      const auto& s = model.samplers[size_t(sampler)];
      img.sampler.wrapS = wrapMode(s.wrapS);
      img.sampler.wrapT = wrapMode(s.wrapT);
      if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) img.sampler.magFilter = GL_NEAREST;
      if (s.minFilter > 0) img.sampler.minFilter = GLenum(s.minFilter);  // glTF uses the GL enums
    }
    const int index = int(scene.images.size());
    scene.images.push_back(std::move(img));
    images[{tex.source, sampler}] = index;
    return index;
  }

  std::string primitive(const tinygltf::Primitive& prim, MeshData& mesh) {
    auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) return "primitive without POSITION";
    std::vector<float> f;
    if (auto e = readAccessor(model, pos->second, 3, f); !e.empty()) return e;
    for (size_t i = 0; i + 2 < f.size(); i += 3) mesh.positions.emplace_back(f[i], f[i + 1], f[i + 2]);
    if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
      if (auto e = readAccessor(model, it->second, 3, f); !e.empty()) return e;
      for (size_t i = 0; i + 2 < f.size(); i += 3) mesh.normals.emplace_back(f[i], f[i + 1], f[i + 2]);
    }
    if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
      if (auto e = readAccessor(model, it->second, 2, f); !e.empty()) return e;
      for (size_t i = 0; i + 1 < f.size(); i += 2) mesh.uvs.emplace_back(f[i], 1.0f - f[i + 1]);  // glTF: v down
    }
    if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end()) {
      // The file's own frames. Its bitangent, cross(N, T) w, points along its +v; we flip v
      // above, so the handedness flips with it.
      if (auto e = readAccessor(model, it->second, 4, f); !e.empty()) return e;
      for (size_t i = 0; i + 3 < f.size(); i += 4)
        mesh.sourceTangents.emplace_back(f[i], f[i + 1], f[i + 2], -f[i + 3]);
    }
    if (prim.indices >= 0) {
      if (auto e = readAccessor(model, prim.indices, 1, f); !e.empty()) return e;
      for (float v : f) {
        if (!(v >= 0.0f && v < 4294967296.0f)) return "an index is not a vertex number";
        mesh.indices.push_back(uint32_t(v));
      }
    } else {
      for (uint32_t i = 0; i < mesh.positions.size(); ++i) mesh.indices.push_back(i);
    }
    mesh.material =
        prim.material >= 0 && size_t(prim.material) < model.materials.size() ? materialBase + prim.material : 0;
    // Checked before anything walks the indices; missing or short normals are then computed.
    const bool ownNormals = mesh.normals.size() == mesh.positions.size();
    if (!ownNormals) mesh.normals.clear();
    if (!mesh.sourceTangents.empty() && mesh.sourceTangents.size() != mesh.positions.size())
      mesh.sourceTangents.clear();
    if (auto e = validateMesh(mesh); !e.empty()) return e;
    if (!ownNormals) computeNormals(mesh);
    return {};
  }

  // A node graph may list a child many times at every level (a DAG, or a cycle the depth limit
  // stops): the number of instances it can make grows exponentially, so visits are budgeted.
  static constexpr int kMaxNodeVisits = 1 << 16;
  int nodeVisits = 0;
  bool nodeBudgetSpent() const { return nodeVisits >= kMaxNodeVisits; }

  void node(int index, const glm::mat4& parent, int depth) {
    if (index < 0 || size_t(index) >= model.nodes.size() || depth > 64 || ++nodeVisits > kMaxNodeVisits) return;
    const auto& n = model.nodes[size_t(index)];
    const glm::mat4 world = parent * nodeTransform(n);
    if (n.mesh >= 0 && size_t(n.mesh) < meshPrimitives.size())
      for (int m : meshPrimitives[size_t(n.mesh)]) scene.instances.push_back({m, world});
    for (int child : n.children) node(child, world, depth + 1);
  }
};

// A glTF names its buffers and images by URI. They are read only when they are regular files
// inside the glTF's own folder (symbolic links followed): a model from the web cannot pull in
// /etc/passwd, a neighbour's folder or an endless device like /dev/zero.
struct ModelFolder {
  fs::path folder;
  bool allows(const std::string& path) const {
    std::error_code ec;
    return fs::is_regular_file(path, ec) && realPathInside(folder, path);
  }
};

bool modelFileExists(const std::string& path, void* user) { return static_cast<ModelFolder*>(user)->allows(path); }

std::string keepPath(const std::string& path, void*) { return path; }

bool readModelFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!static_cast<ModelFolder*>(user)->allows(path)) {
    if (err) *err += "'" + path + "' is not a file beside the glTF (a model reads only files in its own folder)\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "ShadeLab never writes through a model\n";
  return false;
}

// The binary container (glTF 2.0, section 4.4: a 12-byte header, then chunks of an 8-byte header
// and a payload) checked before libtinygltf reads it: Debian's 2.7.0 checks the BIN chunk's length
// against the file without its 8-byte header, so a BIN chunk that claims the file's last bytes
// made it copy up to 8 bytes past the end. "" or what is wrong.
std::string checkGlbChunks(const std::vector<unsigned char>& bytes) {
  const auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  constexpr uint32_t kJson = 0x4E4F534A;
  if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) return "not a binary glTF (no glTF header)";
  const uint64_t length = u32(8);
  if (length > bytes.size())
    return "its header gives " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes.size());
  // Every chunk, BIN or of a type the format lets readers skip, lies inside the file.
  for (uint64_t at = 12, index = 0; at < length; ++index) {
    if (length - at < 8) return "chunk " + std::to_string(index) + " is cut off in its header";
    const uint64_t payload = u32(size_t(at)), type = u32(size_t(at) + 4);
    if (payload > length - at - 8)
      return "chunk " + std::to_string(index) + " claims " + std::to_string(payload) + " bytes, the file has " +
             std::to_string(length - at - 8) + " after its header";
    if (index == 0 && type != kJson) return "its first chunk is not JSON";
    at += 8 + payload;
  }
  return {};
}

}  // namespace

std::string loadGltf(const fs::path& file, Scene& scene) {
  if (std::error_code ec; !fs::is_regular_file(file, ec)) return file.string() + ": no such file";
  ModelFolder folder{fs::absolute(file).parent_path()};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepEncoded, nullptr);
  loader.SetFsCallbacks({modelFileExists, keepPath, readModelFile, refuseWrite, &folder});
  tinygltf::Model model;
  std::string err, warn;
  bool ok;
  if (file.extension() == ".glb") {
    std::vector<unsigned char> bytes;
    if (!tinygltf::ReadWholeFile(&bytes, &err, file.string(), nullptr)) return file.string() + ": cannot be read";
    if (bytes.size() > std::numeric_limits<uint32_t>::max())
      return file.string() + ": over 4 GiB (glTF's binary limit)";
    if (auto why = checkGlbChunks(bytes); !why.empty()) return file.string() + ": " + why;
    ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), folder.folder.string());
  } else {
    ok = loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n')) err.pop_back();
    return file.string() + ": " + (err.empty() ? "not a valid glTF 2.0 file" : err.substr(0, err.find('\n')));
  }
  if (!warn.empty()) scene.warnings.push_back(file.string() + ": " + warn.substr(0, warn.find('\n')));

  Importer im{model, scene, {}, int(scene.materials.size()), {}};
  for (auto& m : model.materials) {
    Material mat;
    mat.name = m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      mat.baseColor =
          glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    mat.metallic = float(pbr.metallicFactor);
    mat.roughness = float(pbr.roughnessFactor);
    mat.baseColorImage = im.image(pbr.baseColorTexture.index);
    mat.metallicRoughnessImage = im.image(pbr.metallicRoughnessTexture.index);
    mat.normalImage = im.image(m.normalTexture.index);
    scene.materials.push_back(mat);
  }
  for (auto& mesh : model.meshes) {
    im.meshPrimitives.emplace_back();
    for (auto& prim : mesh.primitives) {
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
        scene.warnings.push_back(file.string() + ": mesh '" + mesh.name + "': skipped a non-triangle primitive");
        continue;
      }
      MeshData data;
      data.name = mesh.name;
      if (auto e = im.primitive(prim, data); !e.empty()) return file.string() + ": mesh '" + mesh.name + "': " + e;
      im.meshPrimitives.back().push_back(int(scene.meshes.size()));
      scene.meshes.push_back(std::move(data));
    }
  }
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (size_t(sceneIndex) < model.scenes.size()) {
    for (int root : model.scenes[size_t(sceneIndex)].nodes) im.node(root, glm::mat4(1.0f), 0);
    if (im.nodeBudgetSpent())
      scene.warnings.push_back(file.string() + ": the node graph names more than " +
                               std::to_string(Importer::kMaxNodeVisits) + " nodes; the rest were left out");
  } else {
    for (size_t i = 0; i < scene.meshes.size(); ++i) scene.instances.push_back({int(i), glm::mat4(1.0f)});
  }
  if (scene.instances.empty()) return file.string() + ": the glTF scene has no triangle meshes";
  return {};
}

}  // namespace shadelab
