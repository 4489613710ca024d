#include <gtest/gtest.h>

#include <algorithm>

#include <set>

#include "labs/shading/shading_lab.h"

using namespace shadelab;

static std::string setParam(Lab& lab, const std::string& key, const std::string& value) {
  SetFromString s(lab.id(), key, value);
  lab.visitParams(s);
  return s.result();
}

TEST(Params, SetsEveryKind) {
  ShadingLab lab;
  EXPECT_EQ(setParam(lab, "mode", "flat"), "");
  EXPECT_EQ(lab.params.mode, ShadingMode::Flat);
  EXPECT_EQ(setParam(lab, "shininess", "128.5"), "");
  EXPECT_FLOAT_EQ(lab.params.shininess, 128.5f);
  EXPECT_EQ(setParam(lab, "lights", "4"), "");
  EXPECT_EQ(lab.params.lights, 4);
  EXPECT_EQ(setParam(lab, "textures", "off"), "");
  EXPECT_FALSE(lab.params.textures);
}

TEST(Params, RejectsOutOfRangeAndKeepsValue) {
  ShadingLab lab;
  const float before = lab.params.shininess;
  EXPECT_EQ(setParam(lab, "shininess", "0"), "shading.shininess: invalid value '0' (valid: a number in [1, 1024])");
  EXPECT_EQ(setParam(lab, "shininess", "nan"), "shading.shininess: invalid value 'nan' (valid: a number in [1, 1024])");
  EXPECT_EQ(setParam(lab, "shininess", "12abc"),
            "shading.shininess: invalid value '12abc' (valid: a number in [1, 1024])");
  EXPECT_FLOAT_EQ(lab.params.shininess, before);
  EXPECT_EQ(setParam(lab, "lights", "2.5"), "shading.lights: invalid value '2.5' (valid: an integer in [0, 4])");
  EXPECT_EQ(setParam(lab, "lights", "5"), "shading.lights: invalid value '5' (valid: an integer in [0, 4])");
  EXPECT_EQ(setParam(lab, "textures", "maybe"),
            "shading.textures: invalid value 'maybe' (valid: on, off, true, false, 1, 0)");
  EXPECT_EQ(setParam(lab, "mode", "toon"), "shading.mode: invalid value 'toon' (valid: flat, gouraud, phong)");
}

TEST(Params, UnknownKeyListsValidOnes) {
  ShadingLab lab;
  const std::string err = setParam(lab, "bogus", "1");
  EXPECT_NE(err.find("unknown parameter 'shading.bogus'"), std::string::npos);
  EXPECT_NE(err.find("shading.mode"), std::string::npos);
  EXPECT_NE(err.find("shading.light_elevation"), std::string::npos);
}

TEST(Params, TextRoundTripAndReset) {
  ShadingLab lab;
  setParam(lab, "mode", "gouraud");
  setParam(lab, "ka", "0.3333333");
  CollectAsText saved;
  lab.visitParams(saved);
  lab.resetParams();
  EXPECT_EQ(lab.params.mode, ShadingMode::Phong);
  for (auto& [k, v] : saved.values) EXPECT_EQ(setParam(lab, k, v), "") << k << "=" << v;
  EXPECT_EQ(lab.params.mode, ShadingMode::Gouraud);
  EXPECT_FLOAT_EQ(lab.params.ka, 0.3333333f);  // formatNumber keeps every float bit
}

TEST(Params, DescribeListsEveryParamOnce) {
  ShadingLab lab;
  DescribeParams d("shading");
  lab.visitParams(d);
  CollectAsText c;
  lab.visitParams(c);
  std::vector<std::string> params;  // the lines that are not section headings
  for (auto& line : d.lines)
    if (line.rfind("  [", 0) != 0) params.push_back(line);
  EXPECT_EQ(params.size(), c.values.size());
  EXPECT_NE(params.front().find("shading.mode = phong  one of flat, gouraud, phong"), std::string::npos);
}

TEST(Params, NeedsFollowConfiguration) {
  ShadingLab lab;
  EXPECT_TRUE(lab.needs().baseColorTextures);
  EXPECT_FALSE(lab.needs().tangents);  // no normal maps in this lab
  setParam(lab, "textures", "off");
  EXPECT_FALSE(lab.needs().baseColorTextures);
  EXPECT_FALSE(lab.needs().uvs);
}

TEST(Params, ProgramVariantsAreDistinct) {
  ShadingLab lab;
  std::set<std::string> keys;
  for (auto& spec : lab.allPrograms()) EXPECT_TRUE(keys.insert(spec.key()).second) << spec.key();
  // Per mode a pairwise cover (specular, UV interpolation, textures, light count, flat faces): every
  // light count 0..4 of every mode is compiled, in far fewer programs than all 96 + 24 combinations.
  for (const char* mode : {"MODE_FLAT", "MODE_GOURAUD", "MODE_PHONG"})
    for (int lights = 0; lights <= 4; ++lights) {
      const std::string define = "NUM_LIGHTS=" + std::to_string(lights) + ";";
      EXPECT_TRUE(std::any_of(keys.begin(), keys.end(),
                              [&](const std::string& k) {
                                return k.find(mode) != std::string::npos && k.find(define) != std::string::npos;
                              }))
          << mode << " with " << lights << " lights is never compiled";
    }
  EXPECT_LT(keys.size(), 60u);
}

namespace {

// A lab-sized parameter list with a section and an action, visited like a real lab's.
struct ActionParams {
  int seed = 1;
  float level = 0.1f;
  void visit(ParamVisitor& v) {
    v.floatParam({"level", "Noise level", "", "sigma in mean edge lengths"}, level, 0.0f, 1.0f);
    v.section("Noise");
    v.intParam({"seed", "Seed", "", "random seed"}, seed, 0, 1000000);
    v.action({"add_noise", "Add noise", "", "draws new noise: seed + 1"}, [this] { ++seed; });
  }
};

}  // namespace

TEST(Params, ActionsRunByKeyAndAreNoValues) {
  ActionParams p;
  RunAction run("denoise", "add_noise");
  p.visit(run);
  EXPECT_EQ(run.result(), "");
  EXPECT_EQ(p.seed, 2);
  RunAction bad("denoise", "bake");
  p.visit(bad);
  EXPECT_EQ(bad.result(), "unknown action 'denoise.bake' (valid: denoise.add_noise)");
  SetFromString set("denoise", "add_noise", "1");
  p.visit(set);
  EXPECT_EQ(set.result(), "denoise.add_noise is an action, not a value: run it with --do denoise.add_noise");
  CollectAsText text;
  p.visit(text);
  EXPECT_EQ(text.values.size(), 2u) << "an action is no value to save in a preset";
  SetFromString unknown("denoise", "nope", "1");
  p.visit(unknown);
  EXPECT_EQ(unknown.result(), "unknown parameter 'denoise.nope' (valid: denoise.level, denoise.seed)");
}

TEST(Params, ListShowsSectionsAndActions) {
  ActionParams p;
  DescribeParams d("denoise");
  p.visit(d);
  ASSERT_EQ(d.lines.size(), 4u);
  EXPECT_EQ(d.lines[1], "  [Noise]");
  EXPECT_EQ(d.lines[3].rfind("  denoise.add_noise  action (--do denoise.add_noise)", 0), 0u);
}

TEST(Params, AnUnavailableParameterSaysWhyOnlyOnItsOwnLine) {
  int anisotropy = 4, layers = 8;
  DescribeParams d("filtering");
  d.unavailable("this driver has no anisotropic filtering");
  d.intParam({"anisotropy", "Anisotropy", "x", "Probes."}, anisotropy, 1, 16);
  d.intParam({"layers", "Layers", "", "Slices."}, layers, 1, 64);
  ASSERT_EQ(d.lines.size(), 2u);
  EXPECT_NE(d.lines[0].find("(unavailable: this driver has no anisotropic filtering)"), std::string::npos);
  EXPECT_EQ(d.lines[1].find("unavailable"), std::string::npos);
  SetFromString set("filtering", "anisotropy", "8");  // it still holds a value
  set.unavailable("no extension");
  set.intParam({"anisotropy", "Anisotropy", "x", "Probes."}, anisotropy, 1, 16);
  EXPECT_EQ(set.result(), "");
  EXPECT_EQ(anisotropy, 8);
}

TEST(Registry, EachRowMakesTheLabItNames) {
  std::set<std::string_view> seen;
  for (const LabEntry& entry : labRegistry()) {
    EXPECT_TRUE(seen.insert(entry.id).second) << entry.id << " is listed twice";
    const std::unique_ptr<Lab> lab = entry.make();
    ASSERT_NE(lab, nullptr) << entry.id;
    EXPECT_EQ(lab->id(), entry.id);
    EXPECT_EQ(makeLab(entry.id)->id(), entry.id);
  }
  EXPECT_EQ(labIds().size(), labRegistry().size());
  EXPECT_EQ(makeLab("nope"), nullptr);
}

// The judging half of the contract is optional: a lab that only draws implements none of it, and
// every front end that asks for a truth or stress cases gets none instead of a crash.
TEST(Registry, ALabWithoutAJudgeHasNoTruthAndNoStressCases) {
  struct DrawOnly final : LabWithParams<ShadingParams> {
    std::string_view id() const override { return "draw-only"; }
    std::string_view title() const override { return "Draw only"; }
    std::string_view summary() const override { return ""; }
    std::string_view defaultScene() const override { return "sphere"; }
    void visitParams(ParamVisitor&) override {}
    SceneNeeds needs() const override { return {}; }
    std::vector<ProgramSpec> allPrograms() const override { return {}; }
    std::string setup(LabContext&) override { return ""; }
    void render(Frame&) override {}
    std::vector<ProgramRef> activePrograms() const override { return {}; }
  } lab;
  EXPECT_EQ(lab.judge(), nullptr);
  EXPECT_EQ(referenceOf(lab).kind, TruthKind::None);
  EXPECT_TRUE(stressCasesOf(lab).empty());
  ShadingLab judged;
  EXPECT_EQ(judged.judge(), static_cast<Judge*>(&judged));
  EXPECT_NE(referenceOf(judged).kind, TruthKind::None);
}

// A group greys out every parameter inside it with one reason; an outer group's reason wins over an
// inner one and over a parameter's own, and nothing is greyed once the group is left.
TEST(Params, AnUnavailableGroupGreysEachOfItsParametersOnce) {
  int a = 1, b = 1, c = 1, d = 1, e = 1;
  DescribeParams list("shadows");
  {
    const ParamVisitor::UnavailableGroup outer(list, "auto-fit is off");
    list.intParam({"a", "A", "", "."}, a, 0, 2);
    const ParamVisitor::UnavailableGroup inner(list, "fit is not 'cascades'");
    list.unavailable("its own reason");
    list.intParam({"b", "B", "", "."}, b, 0, 2);
  }
  {
    const ParamVisitor::UnavailableGroup inner(list, "fit is not 'cascades'");
    list.intParam({"c", "C", "", "."}, c, 0, 2);
  }
  const ParamVisitor::UnavailableGroup none(list, "");
  list.unavailable("its own reason");
  list.intParam({"d", "D", "", "."}, d, 0, 2);
  list.intParam({"e", "E", "", "."}, e, 0, 2);
  ASSERT_EQ(list.lines.size(), 5u);
  EXPECT_NE(list.lines[0].find("(unavailable: auto-fit is off)"), std::string::npos);
  EXPECT_NE(list.lines[1].find("(unavailable: auto-fit is off)"), std::string::npos);
  EXPECT_NE(list.lines[2].find("(unavailable: fit is not 'cascades')"), std::string::npos);
  EXPECT_NE(list.lines[3].find("(unavailable: its own reason)"), std::string::npos);
  EXPECT_EQ(list.lines[4].find("unavailable"), std::string::npos);
}

// Truths' overrides and stress cases are typed edits of the Params struct, turned into the text the
// host applies: only what the edit changes, spelled as --set takes it.
TEST(Params, ATypedEditBecomesTheSettingsItChanges) {
  ShadingLab lab;
  lab.params.mode = ShadingMode::Flat;
  const ReferenceSpec truth = lab.reference();
  EXPECT_EQ(truth.overrides, (Settings{{"mode", "phong"}, {"tessellation", "256"}}));
  for (auto& [key, value] : truth.overrides) EXPECT_EQ(setParam(lab, key, value), "") << key;
  EXPECT_EQ(lab.params.mode, ShadingMode::Phong);
  EXPECT_EQ(lab.params.tessellation, ShadingLab::kReferenceTessellation);
}
