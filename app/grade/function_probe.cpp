#include "app/grade/function_probe.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>
#include <nlohmann/json.hpp>

#include "app/gl/gl.h"
#include "app/gl/texture.h"
#include "app/grade/trace.h"
#include "app/measure/report.h"
#include "app/shader/shader_library.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr const char* kProbeFile = "shadelab-probe/probe.frag";

bool readText(const nlohmann::json& j, const char* key, std::string& out) {
  if (!j.contains(key) || !j[key].is_string()) return false;
  out = j[key].get<std::string>();
  return true;
}

// A key that is true; false when absent or not a boolean (a rubric is untrusted: never a throw).
bool flag(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_boolean() && j[key].get<bool>();
}

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string parseGenerator(const nlohmann::json& j, const std::string& at, ProbeGenerator& g) {
  if (!j.is_object()) return at + ": must be an object ({\"range\": [lo, hi]}, {\"unit\": true}, ...)";
  if (j.contains("range")) {
    const auto& r = j["range"];
    if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
        !(r[0].get<double>() <= r[1].get<double>()))
      return at + ": \"range\" must be [low, high] with low <= high";
    g.kind = ProbeGenerator::Kind::Range;
    g.low = r[0].get<float>();
    g.high = r[1].get<float>();
  } else if (flag(j, "unit")) {
    g.kind = ProbeGenerator::Kind::Unit;
  } else if (j.contains("hemisphere")) {
    if (!readText(j, "hemisphere", g.around)) return at + ": \"hemisphere\" must name another input";
    g.kind = ProbeGenerator::Kind::Hemisphere;
  } else if (flag(j, "rotation")) {
    g.kind = ProbeGenerator::Kind::Rotation;
  } else if (j.contains("values")) {
    if (!j["values"].is_array() || j["values"].empty()) return at + ": \"values\" must be a non-empty array";
    g.kind = ProbeGenerator::Kind::Values;
    for (auto& v : j["values"]) {
      std::vector<float> value;
      if (v.is_number())
        value.push_back(v.get<float>());
      else if (v.is_array() && std::all_of(v.begin(), v.end(), [](auto& x) { return x.is_number(); }))
        for (auto& x : v) value.push_back(x.get<float>());
      else
        return at + ": \"values\" must hold numbers or arrays of numbers";
      g.values.push_back(value);
    }
  } else {
    return at + ": say how values are drawn: \"range\", \"unit\", \"hemisphere\", \"rotation\" or \"values\"";
  }
  return {};
}

// A small, fixed random sequence: every side draws the same table.
struct Random {
  uint64_t state;
  explicit Random(uint64_t seed) : state(seed * 6364136223846793005ull + 1442695040888963407ull) {}
  float next() {  // [0, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float((state >> 40) & 0xffffff) / float(1 << 24);
  }
  float between(float lo, float hi) { return lo + (hi - lo) * next(); }
  glm::vec3 unit() {
    const float z = between(-1.0f, 1.0f), a = between(0.0f, 6.2831853f), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(a), r * std::sin(a), z};
  }
};

// One input's value as 4-float slots (mat3: three columns).
std::vector<float> drawValue(const ProbeInput& in, const ProbeGenerator& g, Random& rng, size_t row,
                             const std::vector<std::vector<float>>& others, const FunctionProbe& probe) {
  const int n = in.components();
  std::vector<float> v(n, 0.0f);
  switch (g.kind) {
    case ProbeGenerator::Kind::Range:
      for (auto& x : v) x = rng.between(g.low, g.high);
      break;
    case ProbeGenerator::Kind::Unit:
    case ProbeGenerator::Kind::Hemisphere: {
      glm::vec3 u = rng.unit();
      if (n == 2) u = glm::normalize(glm::vec3(u.x, u.y, 0.0f) + glm::vec3(1e-6f, 0.0f, 0.0f));
      if (g.kind == ProbeGenerator::Kind::Hemisphere)
        for (size_t i = 0; i < probe.inputs.size(); ++i)
          if (probe.inputs[i].name == g.around && others[i].size() >= 3) {
            const glm::vec3 a(others[i][0], others[i][1], others[i][2]);
            if (glm::dot(u, a) < 0.0f) u = -u;
          }
      for (int c = 0; c < n && c < 3; ++c) v[c] = u[c];
      break;
    }
    case ProbeGenerator::Kind::Rotation: {  // a right-handed orthonormal frame, as columns
      const glm::vec3 z = rng.unit();
      glm::vec3 x = glm::normalize(glm::cross(std::abs(z.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0), z));
      const float a = rng.between(0.0f, 6.2831853f);
      const glm::vec3 y0 = glm::cross(z, x);
      x = std::cos(a) * x + std::sin(a) * y0;
      const glm::vec3 y = glm::cross(z, x);
      for (int c = 0; c < 3; ++c) {
        v[c] = x[c];
        v[3 + c] = y[c];
        v[6 + c] = z[c];
      }
      break;
    }
    case ProbeGenerator::Kind::Values: {
      const auto& src = g.values[row % g.values.size()];
      for (int c = 0; c < n; ++c) v[c] = src.empty() ? 0.0f : src[std::min<size_t>(c, src.size() - 1)];
      break;
    }
  }
  return v;
}

int slotsOf(const ProbeInput& in) { return in.type == "mat3" ? 3 : 1; }

// The input table: `rows` rows of (values, then the alternative values), 4 floats a slot.
std::vector<float> inputTable(const FunctionProbe& probe, int& width) {
  int slots = 0;
  for (auto& in : probe.inputs) slots += slotsOf(in);
  width = 2 * slots;
  const int rows = probe.totalRows();
  std::vector<float> table(size_t(width) * rows * 4, 0.0f);
  Random rng(0x5eed);
  for (int r = 0; r < rows; ++r) {
    const int edge = r < probe.rows ? -1 : (r - probe.rows) / FunctionProbe::kEdgeRows;
    for (int side = 0; side < 2; ++side) {
      std::vector<std::vector<float>> values(probe.inputs.size());
      for (size_t i = 0; i < probe.inputs.size(); ++i) {
        const ProbeInput& in = probe.inputs[i];
        const ProbeGenerator* g = &in.generator;
        if (edge >= 0)
          for (auto& [name, eg] : probe.edges[edge].inputs)
            if (name == in.name) g = &eg;
        values[i] = drawValue(in, *g, rng, size_t(r), values, probe);
      }
      int slot = 0;
      for (size_t i = 0; i < probe.inputs.size(); ++i) {
        const ProbeInput& in = probe.inputs[i];
        for (int s = 0; s < slotsOf(in); ++s, ++slot) {
          float* texel = &table[(size_t(r) * width + side * slots + slot) * 4];
          const int per = in.type == "mat3" ? 3 : 4;
          for (int c = 0; c < per && s * per + c < in.components(); ++c) texel[c] = values[i][s * per + c];
        }
      }
    }
  }
  return table;
}

const char* swizzle(int n) { return n == 1 ? "x" : n == 2 ? "xy" : n == 3 ? "xyz" : "xyzw"; }

// The generated fragment shader; `traced`: with the trace's taps declared before the includes, and
// the traced point's value written in place of the result when one is chosen.
std::string probeSource(const FunctionProbe& probe, bool traced) {
  int slots = 0;
  for (auto& in : probe.inputs) slots += slotsOf(in);
  std::string s =
      "#version 330 core\n"
      "// The exercised function probed by itself (grade/function_probe.h); written by the grader.\n";
  s += probe.prelude + "\n";
  if (traced) s += tracePrelude();
  for (auto& f : probe.include) s += "#include \"" + f + "\"\n";
  s += probe.helpers + "\n";
  for (auto& [name, kind] : probe.textures)
    if (name.rfind("probe_", 0) == 0) s += "uniform sampler2D " + name + ";\n";
  s += "uniform highp sampler2D shadelab_probeInputs;\n"
       "uniform int shadelab_probeVary;\n"
       "uniform int shadelab_probeTransform;\n"
       "uniform int shadelab_probeQuantity;\n"
       "out vec4 shadelab_probeOut;\n"
       "void main() {\n"
       "  int shadelab_row = int(gl_FragCoord.x);\n"
       "  vec4 shadelab_t, shadelab_a;\n";
  int slot = 0, unit = 0;
  for (auto& in : probe.inputs) {
    const int n = in.components();
    if (in.type == "mat3") {
      s += "  " + in.type + " " + in.name + ";\n";
      for (int c = 0; c < 3; ++c, ++slot) {
        s += "  shadelab_t = texelFetch(shadelab_probeInputs, ivec2(" + std::to_string(slot) + ", shadelab_row), 0);\n";
        s += "  shadelab_a = texelFetch(shadelab_probeInputs, ivec2(" + std::to_string(slots + slot) +
             ", shadelab_row), 0);\n";
        s += "  if (shadelab_probeVary == " + std::to_string(unit) + ") shadelab_t = shadelab_a;\n";
        s += "  " + in.name + "[" + std::to_string(c) + "] = shadelab_t.xyz;\n";
      }
      ++unit;
      continue;
    }
    s += "  shadelab_t = texelFetch(shadelab_probeInputs, ivec2(" + std::to_string(slot) + ", shadelab_row), 0);\n";
    s += "  shadelab_a = texelFetch(shadelab_probeInputs, ivec2(" + std::to_string(slots + slot) +
         ", shadelab_row), 0);\n";
    ++slot;
    if (in.varyComponents) {
      for (int c = 0; c < n; ++c, ++unit)
        s += "  if (shadelab_probeVary == " + std::to_string(unit) + ") shadelab_t." + "xyzw"[c] + " = shadelab_a." +
             "xyzw"[c] + ";\n";
    } else {
      s += "  if (shadelab_probeVary == " + std::to_string(unit++) + ") shadelab_t = shadelab_a;\n";
    }
    s += "  " + in.type + " " + in.name + " = shadelab_t." + swizzle(n) + ";\n";
  }
  for (size_t t = 0; t < probe.transforms.size(); ++t)
    s += "  if (shadelab_probeTransform == " + std::to_string(t) + ") " + probe.transforms[t].input + " = " +
         probe.transforms[t].to + ";\n";
  for (size_t q = 0; q < probe.quantities.size(); ++q)
    s += "  if (shadelab_probeQuantity == " + std::to_string(q) + ") {\n    shadelab_probeOut = vec4(float(" +
         probe.quantities[q].expr + "), 0.0, 0.0, 1.0);\n    return;\n  }\n";
  const char* type = probe.size == 1 ? "float" : probe.size == 2 ? "vec2" : "vec3";
  s += "  vec4 shadelab_r = vec4(0.0, 0.0, 0.0, 1.0);\n";
  s += "  shadelab_r." + std::string(swizzle(probe.size)) + " = " + type + "(" + probe.result + ");\n";
  if (traced) s += "  if (shadelab_trace >= 0) shadelab_r = shadelab_traced;\n";
  s += "  shadelab_probeOut = shadelab_r;\n}\n";
  return s;
}

// A texture the probe binds in place of a lab's map: smooth, not symmetric in u or v.
gl::Texture2D probeTexture(const std::string& kind, std::string& error) {
  constexpr int n = 64;
  gl::SamplerState sampler;
  sampler.minFilter = GL_LINEAR;
  sampler.wrapS = sampler.wrapT = GL_CLAMP_TO_EDGE;
  if (kind == "ramp-r" || kind == "ramp-rgb") {
    std::vector<float> px(size_t(n) * n * 4);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
        float* p = &px[(size_t(y) * n + x) * 4];
        p[0] = 0.1f + 0.5f * u + 0.3f * v * v;
        p[1] = 0.2f + 0.6f * v * v;
        p[2] = 0.5f + 0.3f * u * v;
        p[3] = 1.0f;
      }
    if (kind == "ramp-r") {
      std::vector<float> r(size_t(n) * n);
      for (size_t i = 0; i < r.size(); ++i) r[i] = px[i * 4];
      return gl::Texture2D::fromData({n, n}, GL_R16F, GL_RED, GL_FLOAT, r.data(), sampler);
    }
    return gl::Texture2D::fromData({n, n}, GL_RGBA16F, GL_RGBA, GL_FLOAT, px.data(), sampler);
  }
  if (kind == "levels") {  // every texel of level k holds k: what a lookup returns says which levels it read
    const int levels = 7;
    gl::Texture2D t = gl::Texture2D::allocate({n, n}, GL_RGBA16F, levels);
    t.bind(0);
    for (int k = 0, s = n; k < levels; ++k, s /= 2) {
      std::vector<uint16_t> px(size_t(s) * s * 4);
      const uint16_t half = glm::packHalf1x16(float(k));
      std::fill(px.begin(), px.end(), half);
      glTexSubImage2D(GL_TEXTURE_2D, k, 0, 0, s, s, GL_RGBA, GL_HALF_FLOAT, px.data());
    }
    sampler.minFilter = GL_NEAREST_MIPMAP_NEAREST;
    sampler.magFilter = GL_NEAREST;
    t.setSampler(sampler);
    return t;
  }
  if (kind == "noise-rgb") {  // 16 x 16 texels of unrelated values: a texel read one off shows at once
    constexpr int m = 16;
    std::vector<float> px(size_t(m) * m * 4);
    uint32_t h = 0x9e3779b9u;
    for (auto& v : px) {
      h ^= h << 13;
      h ^= h >> 17;
      h ^= h << 5;
      v = 0.05f + 0.9f * float(h & 0xffffu) / 65535.0f;
    }
    for (size_t i = 3; i < px.size(); i += 4) px[i] = 1.0f;
    sampler.minFilter = sampler.magFilter = GL_NEAREST;
    sampler.wrapS = sampler.wrapT = GL_REPEAT;
    return gl::Texture2D::fromData({m, m}, GL_RGBA16F, GL_RGBA, GL_FLOAT, px.data(), sampler);
  }
  error = "texture kind '" + kind + "' (valid: ramp-r, ramp-rgb, levels, noise-rgb)";
  return {};
}

}  // namespace

int findingRank(const std::string& kind) {
  static const char* const kOrder[] = {"non-finite", "starter", "transform", "relation",
                                       "ignores",    "uses",    "quantity",  "only"};
  for (size_t i = 0; i < std::size(kOrder); ++i)
    if (kind == kOrder[i]) return int(i);
  return -1;
}

int ProbeInput::components() const {
  if (type == "float") return 1;
  if (type == "vec2") return 2;
  if (type == "vec3") return 3;
  if (type == "mat3") return 9;
  return 4;
}

std::vector<std::pair<int, int>> FunctionProbe::variedUnits() const {
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i].varyComponents)
      for (int c = 0; c < inputs[i].components(); ++c) out.push_back({int(i), c});
    else
      out.push_back({int(i), -1});
  }
  return out;
}

std::string FunctionProbe::unitName(int unit) const {
  const auto [i, c] = variedUnits()[unit];
  return inputs[i].name + (c < 0 ? "" : std::string(".") + "xyzw"[c]);
}

std::string FunctionProbe::unitSays(int unit) const {
  const auto [i, c] = variedUnits()[unit];
  return c < 0 ? inputs[i].says : inputs[i].name + "." + "xyzw"[c];
}

std::vector<FunctionProbe::Draw> FunctionProbe::draws() const {
  std::vector<Draw> out;
  for (size_t b = 0; b < blocks.size(); ++b) out.push_back({Draw::Kind::Base, int(b), -1});
  for (size_t u = 0; u < variedUnits().size(); ++u) out.push_back({Draw::Kind::Vary, 0, int(u)});
  for (size_t t = 0; t < transforms.size(); ++t) out.push_back({Draw::Kind::Transform, 0, int(t)});
  for (size_t q = 0; q < quantities.size(); ++q) out.push_back({Draw::Kind::Quantity, 0, int(q)});
  return out;
}

std::string parseFunctionProbe(const nlohmann::json& j, const std::string& where, FunctionProbe& out) {
  if (!j.is_object()) return where + ": not an object";
  out = FunctionProbe{};
  if (!readText(j, "name", out.name) || out.name.empty()) return where + ": \"name\" is missing";
  const std::string at = where + " (" + out.name + ")";
  if (!j.contains("include") || !j["include"].is_array() || j["include"].empty())
    return at + ": \"include\" must list the files that bring the function in";
  for (auto& f : j["include"]) {
    if (!f.is_string() || f.get<std::string>().empty() || f.get<std::string>().find("..") != std::string::npos)
      return at + ": \"include\" must hold shader paths without \"..\"";
    out.include.push_back(f.get<std::string>());
  }
  readText(j, "prelude", out.prelude);
  readText(j, "helpers", out.helpers);
  if (j.contains("defines")) {
    if (!j["defines"].is_object()) return at + ": \"defines\" must be an object NAME -> value";
    for (auto& [k, v] : j["defines"].items()) {
      if (!identifier(k)) return at + ": \"defines\": '" + k + "' is not a GLSL name";
      out.defines.push_back({k, v.is_string() ? v.get<std::string>() : v.dump()});
    }
  }
  if (!readText(j, "result", out.result) || out.result.empty())
    return at + ": \"result\" must be a GLSL expression of the inputs";
  if (!j.contains("size") || !j["size"].is_number_integer() || j["size"].get<int>() < 1 || j["size"].get<int>() > 3)
    return at + ": \"size\" must be 1, 2 or 3 (the result's components)";
  out.size = j["size"].get<int>();
  if (!readText(j, "says", out.says) || out.says.empty()) return at + ": \"says\" must name the result for a student";
  out.components = out.size == 1 ? "" : out.size == 2 ? "x, y" : "x, y, z";
  readText(j, "components", out.components);
  if (!j.contains("inputs") || !j["inputs"].is_array() || j["inputs"].empty())
    return at + ": \"inputs\" must be a non-empty array";
  for (size_t i = 0; i < j["inputs"].size(); ++i) {
    const auto& ji = j["inputs"][i];
    const std::string ai = at + ": inputs[" + std::to_string(i) + "]";
    ProbeInput in;
    if (!ji.is_object() || !readText(ji, "name", in.name) || !identifier(in.name))
      return ai + ": \"name\" must be a GLSL name";
    if (!readText(ji, "type", in.type) ||
        (in.type != "float" && in.type != "vec2" && in.type != "vec3" && in.type != "vec4" && in.type != "mat3"))
      return ai + ": \"type\" must be float, vec2, vec3, vec4 or mat3";
    if (!readText(ji, "says", in.says) || in.says.empty()) return ai + ": \"says\" must name the input for a student";
    if (auto e = parseGenerator(ji, ai, in.generator); !e.empty()) return e;
    std::string vary;
    in.varyComponents = readText(ji, "vary", vary) && vary == "components";
    if (in.varyComponents && in.type == "mat3") return ai + ": \"vary\": \"components\" is for vectors";
    out.inputs.push_back(std::move(in));
  }
  const auto inputNamed = [&](const std::string& name) {
    return std::any_of(out.inputs.begin(), out.inputs.end(), [&](const ProbeInput& in) { return in.name == name; });
  };
  if (j.contains("uniforms")) {
    if (!j["uniforms"].is_array()) return at + ": \"uniforms\" must be an array of blocks";
    for (size_t b = 0; b < j["uniforms"].size(); ++b) {
      const auto& jb = j["uniforms"][b];
      const std::string ab = at + ": uniforms[" + std::to_string(b) + "]";
      ProbeBlock block;
      if (!jb.is_object() || !readText(jb, "says", block.says)) return ab + ": \"says\" is missing";
      readText(jb, "name", block.name);
      readText(jb, "varies", block.varies);
      if (!jb.contains("set") || !jb["set"].is_object()) return ab + ": \"set\" must be an object uniform -> value";
      for (auto& [name, v] : jb["set"].items()) {
        std::vector<float> value;
        if (v.is_number())
          value.push_back(v.get<float>());
        else if (v.is_array() && v.size() >= 2 && v.size() <= 4 &&
                 std::all_of(v.begin(), v.end(), [](auto& x) { return x.is_number(); }))
          for (auto& x : v) value.push_back(x.get<float>());
        else
          return ab + ": \"set\"." + name + " must be a number or 2 to 4 numbers";
        block.uniforms.push_back({name, value});
      }
      if (block.name.empty())
        block.name = block.uniforms.empty() ? "block-" + std::to_string(b) : block.uniforms[0].first;
      out.blocks.push_back(std::move(block));
    }
  }
  if (out.blocks.empty()) out.blocks.push_back({"defaults", "the lab's defaults", "", {}});
  if (j.contains("textures")) {
    if (!j["textures"].is_object()) return at + ": \"textures\" must be an object sampler -> kind";
    for (auto& [name, kind] : j["textures"].items()) {
      if (!identifier(name) || !kind.is_string()) return at + ": \"textures\"." + name + " must name a kind";
      const std::string k = kind.get<std::string>();
      if (k != "ramp-r" && k != "ramp-rgb" && k != "levels" && k != "noise-rgb")
        return at + ": \"textures\"." + name + " is '" + k + "' (valid: ramp-r, ramp-rgb, levels, noise-rgb)";
      out.textures.push_back({name, k});
    }
  }
  if (j.contains("edges")) {
    if (!j["edges"].is_array()) return at + ": \"edges\" must be an array";
    for (size_t e = 0; e < j["edges"].size(); ++e) {
      const auto& je = j["edges"][e];
      const std::string ae = at + ": edges[" + std::to_string(e) + "]";
      ProbeEdge edge;
      if (!je.is_object() || !readText(je, "name", edge.name) || !readText(je, "says", edge.says))
        return ae + ": \"name\" and \"says\" are needed";
      if (!je.contains("inputs") || !je["inputs"].is_object() || je["inputs"].empty())
        return ae + ": \"inputs\" must give some inputs other values";
      for (auto& [name, jg] : je["inputs"].items()) {
        if (!inputNamed(name)) return ae + ": \"inputs\"." + name + " is not an input";
        ProbeGenerator g;
        if (auto err = parseGenerator(jg, ae + ": \"inputs\"." + name, g); !err.empty()) return err;
        edge.inputs.push_back({name, g});
      }
      out.edges.push_back(std::move(edge));
    }
  }
  if (j.contains("transforms")) {
    if (!j["transforms"].is_array()) return at + ": \"transforms\" must be an array";
    for (size_t t = 0; t < j["transforms"].size(); ++t) {
      const auto& jt = j["transforms"][t];
      ProbeTransform tr;
      const std::string a = at + ": transforms[" + std::to_string(t) + "]";
      if (!jt.is_object() || !readText(jt, "name", tr.name) || !readText(jt, "says", tr.says) ||
          !readText(jt, "input", tr.input) || !readText(jt, "to", tr.to))
        return a + ": \"name\", \"says\", \"input\" and \"to\" are needed";
      if (!inputNamed(tr.input)) return a + ": \"input\" '" + tr.input + "' is not an input";
      out.transforms.push_back(std::move(tr));
    }
  }
  if (j.contains("quantities")) {
    if (!j["quantities"].is_array()) return at + ": \"quantities\" must be an array";
    for (size_t q = 0; q < j["quantities"].size(); ++q) {
      const auto& jq = j["quantities"][q];
      ProbeQuantity qu;
      if (!jq.is_object() || !readText(jq, "name", qu.name) || !readText(jq, "says", qu.says) ||
          !readText(jq, "expr", qu.expr))
        return at + ": quantities[" + std::to_string(q) + "]: \"name\", \"says\" and \"expr\" are needed";
      out.quantities.push_back(std::move(qu));
    }
  }
  if (j.contains("rows")) {
    if (!j["rows"].is_number_integer() || j["rows"].get<int>() < 16 || j["rows"].get<int>() > 1024)
      return at + ": \"rows\" must be an integer in [16, 1024]";
    out.rows = j["rows"].get<int>();
  }
  if (out.totalRows() > 2048) return at + ": too many edges (the table holds at most 2048 rows)";
  // A table a driver draws at once: a few inputs, at most 64 draws.
  if (out.inputs.size() > 16) return at + ": \"inputs\": at most 16";
  if (out.draws().size() > 64)
    return at + ": too many uniform blocks, varied inputs, transforms and quantities (at most 64 draws in all)";
  return {};
}

namespace {

// The probe's draws (trace == nullptr), or one draw per traced point at the first block's inputs.
std::string drawProbe(const FunctionProbe& probe, const std::vector<fs::path>& roots, const ProbeTrace* trace,
                      ImageF& image, std::vector<std::string>& errors) {
  // The generated file lives in a folder of its own, searched first: nothing a student hands in
  // can stand in for it.
  struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("shadelab-probe-" + std::to_string(getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } scratch;
  if (auto e = writeTextFile((scratch.dir / kProbeFile).string(), probeSource(probe, trace != nullptr)); !e.empty())
    return e;
  if (trace)  // the instrumented file in place of the one it was made from
    if (auto e = writeTextFile((scratch.dir / trace->file).string(), trace->text); !e.empty()) return e;
  std::vector<fs::path> searched{scratch.dir};
  searched.insert(searched.end(), roots.begin(), roots.end());
  ShaderLibrary library{ShaderSearchPath(searched)};
  library.onDiagnostic = [](const Diagnostic&) {};  // said once, as the grader's errors
  ProgramSpec spec{"probe of " + probe.name,
                   {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, kProbeFile}},
                   probe.defines};
  ProgramRef program = library.program(spec);
  std::vector<FunctionProbe::Draw> draws = probe.draws();
  if (trace)
    draws.assign(size_t(std::max(trace->points, 0)),
                 FunctionProbe::Draw{FunctionProbe::Draw::Kind::Base,
                                     std::clamp(trace->block, 0, int(probe.blocks.size()) - 1), -1});
  const glm::ivec2 size{probe.totalRows(), std::max(int(draws.size()), 1)};
  image = ImageF{size, std::vector<float>(size_t(size.x) * size.y * 4, 0.0f)};
  if (!program->hasGoodProgram()) {
    for (auto& d : program->diagnostics())
      if (d.isError) errors.push_back(spec.name + ": " + d.formatWithCaret());
    if (errors.empty()) errors.push_back(spec.name + ": did not build (no message from the driver)");
    return {};
  }
  int width = 0;
  const std::vector<float> table = inputTable(probe, width);
  gl::SamplerState nearest;
  nearest.minFilter = nearest.magFilter = GL_NEAREST;
  nearest.wrapS = nearest.wrapT = GL_CLAMP_TO_EDGE;
  const gl::Texture2D inputs =
      gl::Texture2D::fromData({width, probe.totalRows()}, GL_RGBA32F, GL_RGBA, GL_FLOAT, table.data(), nearest);
  std::vector<gl::Texture2D> textures;
  for (auto& [name, kind] : probe.textures) {
    std::string error;
    textures.push_back(probeTexture(kind, error));
    if (!error.empty()) return error;
  }
  const gl::RenderTarget target = gl::RenderTarget::create(size, GL_RGBA32F);
  const gl::VertexArray vao = gl::VertexArray::make();
  target.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(vao.get());
  program->use();
  inputs.bind(0);
  program->set("shadelab_probeInputs", 0);
  for (size_t t = 0; t < textures.size(); ++t) {
    textures[t].bind(int(t) + 1);
    program->set(probe.textures[t].first.c_str(), int(t) + 1);
  }
  // The block's values as each uniform is declared (an int, u_maxLevel, from a whole number): the
  // program's active uniforms read once, a block's values set only when the block changes.
  GLint current = 0, count = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  glGetProgramiv(GLuint(current), GL_ACTIVE_UNIFORMS, &count);
  std::map<std::string, GLenum> types;
  for (GLint i = 0; i < count; ++i) {
    char buffer[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(GLuint(current), GLuint(i), sizeof buffer, nullptr, &size, &type, buffer);
    types[buffer] = type;
  }
  const auto setUniform = [&](const std::string& name, const std::vector<float>& v) {
    const auto it = types.find(name);
    if (it == types.end()) return;  // not read by this function
    const GLint location = glGetUniformLocation(GLuint(current), name.c_str());
    const GLenum type = it->second;
    if (type == GL_INT || type == GL_BOOL) glUniform1i(location, GLint(std::lround(v[0])));
    if (type == GL_FLOAT) glUniform1f(location, v[0]);
    if (type == GL_FLOAT_VEC2 && v.size() >= 2) glUniform2f(location, v[0], v[1]);
    if (type == GL_FLOAT_VEC3 && v.size() >= 3) glUniform3f(location, v[0], v[1], v[2]);
    if (type == GL_FLOAT_VEC4 && v.size() >= 4) glUniform4f(location, v[0], v[1], v[2], v[3]);
  };
  int block = -1;
  for (size_t d = 0; d < draws.size(); ++d) {
    const FunctionProbe::Draw& draw = draws[d];
    if (draw.block != block)
      for (auto& [name, v] : probe.blocks[size_t(block = draw.block)].uniforms) setUniform(name, v);
    program->set("shadelab_probeVary", draw.kind == FunctionProbe::Draw::Kind::Vary ? draw.index : -1);
    program->set("shadelab_probeTransform", draw.kind == FunctionProbe::Draw::Kind::Transform ? draw.index : -1);
    program->set("shadelab_probeQuantity", draw.kind == FunctionProbe::Draw::Kind::Quantity ? draw.index : -1);
    if (trace) program->set("shadelab_trace", int(d));
    glViewport(0, size.y - 1 - int(d), size.x, 1);  // image rows run top-down
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  image = ImageF{size, target.readRgba()};
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return {};
}

}  // namespace

std::string drawFunctionProbe(const FunctionProbe& probe, const std::vector<fs::path>& roots, ImageF& image,
                              std::vector<std::string>& errors) {
  return drawProbe(probe, roots, nullptr, image, errors);
}

std::string drawFunctionTrace(const FunctionProbe& probe, const std::vector<fs::path>& roots, const ProbeTrace& trace,
                              ImageF& image, std::vector<std::string>& errors) {
  return drawProbe(probe, roots, &trace, image, errors);
}

}  // namespace shadelab
