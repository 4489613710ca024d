#include "app/grade/function_probe.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace shadelab {
namespace {

// A probe of f(v, k) = v * k * gain, read back as the GL side would write it: one pixel per row,
// one image row per draw (base per block, each input varied, the transform, the quantity).
const char* kProbe = R"json({
  "name": "the function by itself",
  "include": ["lab/f.glsl"],
  "result": "f(v, k)",
  "size": 3,
  "says": "result",
  "inputs": [
    {"name": "v", "type": "vec3", "says": "the vector v", "range": [-1, 1]},
    {"name": "k", "type": "float", "says": "the weight k", "range": [0.5, 1]}
  ],
  "uniforms": [
    {"name": "unit-gain", "says": "at gain 1", "set": {"u_gain": 1}},
    {"name": "gain", "says": "where the gain is not 1", "varies": "the gain u_gain", "set": {"u_gain": 2}}
  ],
  "edges": [{"name": "big-k", "says": "where k is above 2", "inputs": {"k": {"range": [3, 4]}}}],
  "transforms": [{"name": "v-turned", "says": "v turned round", "input": "v", "to": "-v"}],
  "quantities": [{"name": "k", "says": "the weight k", "expr": "k"}],
  "rows": 16
})json";

FunctionProbe probe() {
  FunctionProbe p;
  EXPECT_EQ(parseFunctionProbe(nlohmann::json::parse(kProbe), "rubric.json: probes[0]", p), "");
  return p;
}

using Function = std::function<glm::vec3(glm::vec3 v, float k, float gain)>;

ImageF table(const FunctionProbe& p, const Function& f) {
  const auto draws = p.draws();
  ImageF image{{p.totalRows(), int(draws.size())}, {}};
  image.rgba.assign(size_t(image.size.x) * image.size.y * 4, 1.0f);
  for (int r = 0; r < image.size.x; ++r) {
    const glm::vec3 v(std::sin(r * 1.3f), std::cos(r * 0.7f), 0.3f + 0.01f * r), v2(std::cos(2.0f * r), 0.4f, -0.5f);
    const float k = r < p.rows ? 0.5f + 0.02f * r : 3.0f + 0.01f * r, k2 = 0.2f + 0.013f * r;
    for (size_t d = 0; d < draws.size(); ++d) {
      const auto& draw = draws[d];
      glm::vec3 out;
      switch (draw.kind) {
        case FunctionProbe::Draw::Kind::Base:
          out = f(v, k, draw.block == 0 ? 1.0f : 2.0f);
          break;
        case FunctionProbe::Draw::Kind::Vary:
          out = draw.index == 0 ? f(v2, k, 1.0f) : f(v, k2, 1.0f);
          break;
        case FunctionProbe::Draw::Kind::Transform:
          out = f(-v, k, 1.0f);
          break;
        case FunctionProbe::Draw::Kind::Quantity:
          out = glm::vec3(k, 0.0f, 0.0f);
          break;
      }
      float* px = image.at(r, int(d));
      px[0] = out.x;
      px[1] = out.y;
      px[2] = out.z;
    }
  }
  return image;
}

const Function kSolution = [](glm::vec3 v, float k, float gain) { return v * k * gain; };

// The finding the diagnosis says: the most telling by findingRank.
ProbeFinding first(const Function& student) {
  const FunctionProbe p = probe();
  const auto findings = analyseProbe(p, table(p, student), table(p, kSolution), nullptr);
  const ProbeFinding* best = nullptr;
  for (auto& f : findings)
    if (findingRank(f.kind) >= 0 && (!best || findingRank(f.kind) < findingRank(best->kind))) best = &f;
  return best ? *best : findings.empty() ? ProbeFinding{} : findings.front();
}

TEST(FunctionProbe, TheSameFunctionAgrees) {
  const FunctionProbe p = probe();
  const auto findings = analyseProbe(p, table(p, kSolution), table(p, kSolution), nullptr);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].kind, "agrees");
}

TEST(FunctionProbe, ARelationOfTheResults) {
  const ProbeFinding f = first([](glm::vec3 v, float k, float g) { return 0.5f * v * k * g; });
  EXPECT_EQ(f.kind, "relation");
  EXPECT_EQ(f.key, "scaled");
  EXPECT_NE(f.text.find("scaled by 0.5"), std::string::npos) << f.text;
  const ProbeFinding swapped = first([](glm::vec3 v, float k, float g) { return glm::vec3(v.y, v.x, v.z) * k * g; });
  EXPECT_EQ(swapped.key, "swapped-xy") << swapped.text;
}

TEST(FunctionProbe, AnInputTurnedRound) {
  const ProbeFinding f =
      first([](glm::vec3 v, float k, float g) { return glm::vec3(-v.x, -v.y, -v.z) * k * g + 0.0f; });
  EXPECT_EQ(f.kind, "transform");  // -f(v) is also f(-v): the input turned round is said first
  EXPECT_EQ(f.key, "v-turned");
}

TEST(FunctionProbe, AnIgnoredInputAndAnIgnoredUniform) {
  const ProbeFinding k = first([](glm::vec3 v, float, float g) { return v * g; });
  EXPECT_EQ(k.kind, "ignores");
  EXPECT_EQ(k.key, "k");
  EXPECT_NE(k.text.find("the weight k does not reach your result"), std::string::npos) << k.text;
  const ProbeFinding gain = first([](glm::vec3 v, float k, float) { return v * k; });
  EXPECT_EQ(gain.kind, "ignores");
  EXPECT_EQ(gain.key, "gain");
}

TEST(FunctionProbe, ScaledByAQuantityOfTheInputs) {
  const ProbeFinding f = first([](glm::vec3 v, float k, float g) { return v * k * k * g; });
  EXPECT_EQ(f.kind, "quantity");
  EXPECT_EQ(f.key, "k");
  EXPECT_NE(f.text.find("multiplied by the weight k"), std::string::npos) << f.text;
}

TEST(FunctionProbe, WhereTheyDiffer) {
  const ProbeFinding edge = first([](glm::vec3 v, float k, float g) { return v * std::min(k, 2.0f) * g; });
  EXPECT_EQ(edge.kind, "only");
  EXPECT_EQ(edge.key, "big-k");
  EXPECT_NE(edge.text.find("differs only where k is above 2"), std::string::npos) << edge.text;
  const ProbeFinding block = first([](glm::vec3 v, float k, float g) { return v * k * g * g; });
  EXPECT_EQ(block.kind, "only");
  EXPECT_EQ(block.key, "gain");
}

TEST(FunctionProbe, NonFiniteResults) {
  const ProbeFinding f =
      first([](glm::vec3 v, float k, float g) { return k > 2.0f ? glm::vec3(std::nanf("")) : v * k * g; });
  EXPECT_EQ(f.kind, "non-finite");
  EXPECT_NE(f.text.find("all of them where k is above 2"), std::string::npos) << f.text;
}

TEST(FunctionProbe, BadRubricsAreNamedByKey) {
  FunctionProbe p;
  nlohmann::json j = nlohmann::json::parse(kProbe);
  j["size"] = 4;
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("\"size\" must be 1, 2 or 3"), std::string::npos);
  j = nlohmann::json::parse(kProbe);
  j["inputs"][0]["type"] = "sampler2D";
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("inputs[0]: \"type\""), std::string::npos);
  j = nlohmann::json::parse(kProbe);
  j["transforms"][0]["input"] = "w";
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("'w' is not an input"), std::string::npos);
  j = nlohmann::json::parse(kProbe);
  j["textures"] = {{"u_map", "checker"}};
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("valid: ramp-r, ramp-rgb, levels"), std::string::npos);
  j = nlohmann::json::parse(kProbe);
  j["inputs"][0].erase("range");
  j["inputs"][0]["unit"] = "yes";  // not a boolean: no way of drawing it, and no throw
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("say how values are drawn"), std::string::npos);
  j = nlohmann::json::parse(kProbe);
  j["inputs"][0]["vary"] = 3;
  EXPECT_EQ(parseFunctionProbe(j, "r.json: probes[0]", p), "");
  EXPECT_FALSE(p.inputs[0].varyComponents);
  j = nlohmann::json::parse(kProbe);
  j["include"] = {"../../etc/passwd"};
  EXPECT_NE(parseFunctionProbe(j, "r.json: probes[0]", p).find("without \"..\""), std::string::npos);
}

}  // namespace
}  // namespace shadelab
