// Stanford PLY, ASCII and binary (either byte order): vertex x y z, optional normals (nx ny nz)
// and texture coordinates (s t, u v or texture_u texture_v), faces as index lists (fans for
// polygons). Other elements and properties are read past and ignored.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "app/scene/loaders.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

enum class Format { Ascii, Little, Big };

struct Property {
  std::string name, type;
  bool list = false;
  std::string countType;  // list only
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> properties;
};

size_t sizeOf(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

// One scalar of type `t` from the stream, as double. False at the end of the data.
bool readScalar(std::istream& in, Format f, const std::string& t, double& out) {
  if (f == Format::Ascii) {  // strtod, unlike >>, reads nan and inf: the validator then names them
    std::string token;
    if (!(in >> token)) return false;
    char* end = nullptr;
    out = std::strtod(token.c_str(), &end);
    return *end == '\0';
  }
  unsigned char b[8];
  const size_t n = sizeOf(t);
  if (!in.read(reinterpret_cast<char*>(b), std::streamsize(n))) return false;
  if ((f == Format::Big) != (std::endian::native == std::endian::big))
    for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
  if (t == "char" || t == "int8")
    out = double(int8_t(b[0]));
  else if (t == "uchar" || t == "uint8")
    out = double(b[0]);
  else if (t == "short" || t == "int16") {
    int16_t v;
    std::memcpy(&v, b, 2);
    out = v;
  } else if (t == "ushort" || t == "uint16") {
    uint16_t v;
    std::memcpy(&v, b, 2);
    out = v;
  } else if (t == "int" || t == "int32") {
    int32_t v;
    std::memcpy(&v, b, 4);
    out = v;
  } else if (t == "uint" || t == "uint32") {
    uint32_t v;
    std::memcpy(&v, b, 4);
    out = v;
  } else if (t == "float" || t == "float32") {
    float v;
    std::memcpy(&v, b, 4);
    out = v;
  } else {
    double v;
    std::memcpy(&v, b, 8);
    out = v;
  }
  return true;
}

// A double from the file as float: values past float's range become infinite (the validator names
// a position that is), never an out-of-range conversion.
float toFloat(double v) {
  constexpr double kMax = 3.4028234663852886e38;
  return std::isnan(v) ? std::numeric_limits<float>::quiet_NaN()
         : v > kMax    ? std::numeric_limits<float>::infinity()
         : v < -kMax   ? -std::numeric_limits<float>::infinity()
                       : float(v);
}

}  // namespace

std::string loadPly(const fs::path& file, Scene& scene) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return file.string() + ": no such file";
  const std::string where = file.string() + ": ";
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
    return where + "not a PLY file (the first line must be ply)";
  Format format = Format::Ascii;
  std::vector<Element> elements;
  bool sawFormat = false;
  for (;;) {
    if (!std::getline(in, line)) return where + "the header has no end_header";
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") break;
    if (word == "format") {
      std::string name;
      words >> name;
      if (name == "ascii")
        format = Format::Ascii;
      else if (name == "binary_little_endian")
        format = Format::Little;
      else if (name == "binary_big_endian")
        format = Format::Big;
      else
        return where + "unknown format '" + name + "' (valid: ascii, binary_little_endian, binary_big_endian)";
      sawFormat = true;
    } else if (word == "element") {
      Element e;
      if (!(words >> e.name >> e.count)) return where + "malformed element line: " + line;
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) return where + "a property before any element";
      Property p;
      words >> p.type;
      if (p.type == "list") {
        p.list = true;
        words >> p.countType >> p.type;
        if (!sizeOf(p.countType)) return where + "unknown list count type '" + p.countType + "'";
      }
      words >> p.name;
      if (!sizeOf(p.type)) return where + "unknown property type '" + p.type + "' for " + p.name;
      elements.back().properties.push_back(p);
    }
  }
  if (!sawFormat) return where + "the header names no format";

  MeshData mesh;
  mesh.name = file.stem().string();
  bool hasNormals = false, hasUvs = false;
  for (auto& e : elements) {
    const bool vertices = e.name == "vertex", faces = e.name == "face";
    if (vertices) {
      for (auto& p : e.properties) {
        hasNormals |= p.name == "nx";
        hasUvs |= p.name == "s" || p.name == "u" || p.name == "texture_u";
      }
      if (e.count > 50'000'000) return where + "too many vertices (" + std::to_string(e.count) + ")";
    }
    // An element with no properties occupies no bytes: its count, whatever the file says, reads nothing.
    if (e.properties.empty()) continue;
    for (size_t i = 0; i < e.count; ++i) {
      glm::vec3 p(0.0f), n(0.0f);
      glm::vec2 uv(0.0f);
      for (auto& prop : e.properties) {
        if (prop.list) {
          double count = 0;
          if (!readScalar(in, format, prop.countType, count) || !(count >= 0 && count <= 65536) ||
              count != std::floor(count))
            return where + e.name + " " + std::to_string(i) + " is missing or malformed";
          std::vector<uint32_t> poly(static_cast<size_t>(count));
          for (auto& index : poly) {
            double v = 0;
            if (!readScalar(in, format, prop.type, v) || !(v >= 0 && v < 4294967296.0) || v != std::floor(v))
              return where + e.name + " " + std::to_string(i) + " is malformed";
            index = uint32_t(v);
          }
          const bool isIndices = prop.name == "vertex_indices" || prop.name == "vertex_index";
          if (faces && isIndices) {
            if (poly.size() < 3) return where + "face " + std::to_string(i) + " has too few indices";
            for (size_t k = 1; k + 1 < poly.size(); ++k)
              mesh.indices.insert(mesh.indices.end(), {poly[0], poly[k], poly[k + 1]});
          }
          continue;
        }
        double v = 0;
        if (!readScalar(in, format, prop.type, v))
          return where + e.name + " " + std::to_string(i) + " is missing or malformed";
        if (!vertices) continue;
        const std::string& name = prop.name;
        if (name == "x")
          p.x = toFloat(v);
        else if (name == "y")
          p.y = toFloat(v);
        else if (name == "z")
          p.z = toFloat(v);
        else if (name == "nx")
          n.x = toFloat(v);
        else if (name == "ny")
          n.y = toFloat(v);
        else if (name == "nz")
          n.z = toFloat(v);
        else if (name == "s" || name == "u" || name == "texture_u")
          uv.x = toFloat(v);
        else if (name == "t" || name == "v" || name == "texture_v")
          uv.y = toFloat(v);
      }
      if (vertices) {
        mesh.positions.push_back(p);
        if (hasNormals) mesh.normals.push_back(n);
        if (hasUvs) mesh.uvs.push_back(uv);
      }
    }
  }
  if (mesh.indices.empty()) return where + "no faces in PLY file";
  // A file's normals or UVs that are not finite would reach the shaders as NaN: normals are then
  // computed from the faces instead, and such UVs read as 0, each with a warning.
  auto finite = [](const auto& v) {
    for (int c = 0; c < v.length(); ++c)
      if (!std::isfinite(v[c])) return false;
    return true;
  };
  if (!std::all_of(mesh.normals.begin(), mesh.normals.end(), finite)) {
    mesh.normals.clear();
    scene.warnings.push_back(where + "some vertex normals are NaN or Inf; normals computed from the faces instead");
  }
  if (!std::all_of(mesh.uvs.begin(), mesh.uvs.end(), finite)) {
    for (auto& uv : mesh.uvs)
      if (!finite(uv)) uv = glm::vec2(0.0f);
    scene.warnings.push_back(where + "some texture coordinates are NaN or Inf; read as 0");
  }
  if (auto err = validateMesh(mesh); !err.empty()) return where + err;
  if (mesh.normals.empty()) computeNormals(mesh);
  scene.instances.push_back({int(scene.meshes.size()), glm::mat4(1.0f)});
  scene.meshes.push_back(std::move(mesh));
  return {};
}

}  // namespace shadelab
