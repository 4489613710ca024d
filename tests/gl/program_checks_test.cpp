// Checks on what labs hand the GPU, for every registered lab: the uniforms a lab sets exist in the
// program, what it draws for random settings is covered by the variant space check-shaders
// compiles, and each driver caveat's workaround runs on its driver only.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "app/gl/driver_caveats.h"
#include "app/host/random_settings.h"
#include "gl_test.h"

using namespace shadelab;

// A lab that sets a uniform no stage declares (a typo, a renamed uniform) fails loudly where checks
// are on; a declared uniform the compiler dropped does not, nor does any name once a student's file
// stands in.
TEST(Uniforms, AMisspeltNameFailsLoudly) {
  const bool was = uniformChecks();
  setUniformChecks(true);
  ShaderLibrary lib(test::builtinShaders());
  ProgramSpec spec;
  spec.name = "shading/phong";
  spec.stages = {{GL_VERTEX_SHADER, "shading/shade.vert"}, {GL_FRAGMENT_SHADER, "shading/shade.frag"}};
  spec.defines = {{"MODE_PHONG", "1"}, {"NUM_LIGHTS", "2"}};
  auto p = lib.program(spec);
  ASSERT_TRUE(p->hasGoodProgram());
  p->use();
  EXPECT_NO_THROW(p->set("u_eye", glm::vec3(0.0f)));
  EXPECT_NO_THROW(p->set("u_baseColorMap", 0));  // declared under BASE_COLOR_MAP: dropped here, not misspelt
  EXPECT_THROW(p->set("u_eyes", glm::vec3(0.0f)), UnknownUniform);
  try {
    p->set("u_baseColour", glm::vec4(1.0f));
    ADD_FAILURE() << "a misspelt uniform was set without a word";
  } catch (const UnknownUniform& e) {
    EXPECT_NE(std::string(e.what()).find("'u_baseColour'"), std::string::npos) << e.what();
  }
  const auto& set = p->uniformsSet();
  EXPECT_NE(std::find(set.begin(), set.end(), "u_eye"), set.end()) << "the Shaders panel lists what the lab sets";
  setUniformChecks(was);
}

// What every lab draws is covered by the variant space check-shaders compiles (allPrograms()), for
// random settings drawn from its own parameter list. A lab's space is a pairwise cover, not every
// combination (the shadows lab's would be tens of thousands): every define of a drawn program, and
// every pair of them, appears in some program of the space with the same stages. A value or pair
// missing there is a combination nobody compiled before a student met it. Each lab comes from the
// registry, so a new lab is covered without a line here.
TEST(Shaders, EveryLabDrawsOnlyWhatItsVariantSpaceCovers) {
  std::mt19937 rng(11);
  for (auto& id : labIds()) {
    LabHost host(test::builtinShaders());
    ASSERT_EQ(host.selectLab(id), "");
    const auto stagesOf = [](const ProgramSpec& spec) {
      std::string key;
      for (auto& st : spec.stages) key += st.path + "|";
      return key;
    };
    const auto definesOf = [](const ProgramSpec& spec) {
      std::vector<std::string> out;
      for (auto& [name, value] : spec.defines) out.push_back(name + "=" + value);
      return out;
    };
    std::map<std::string, std::vector<std::set<std::string>>> space;  // stages -> each program's defines
    for (auto& spec : host.lab().allPrograms()) {
      const auto d = definesOf(spec);
      space[stagesOf(spec)].emplace_back(d.begin(), d.end());
    }
    int checked = 0;
    for (int round = 0; round < 8; ++round) {
      if (round > 0) host.applySettings(randomSettings(host.lab(), rng));
      host.settle();
      host.renderFrame({48, 32}, 0.0f, 1.0f / 60.0f);
      for (auto& p : host.lab().activePrograms()) {
        const ProgramSpec& spec = p->spec();
        const auto it = space.find(stagesOf(spec));
        ASSERT_NE(it, space.end()) << id << " draws with stages " << stagesOf(spec)
                                   << ", which allPrograms() never uses";
        const auto d = definesOf(spec);
        for (size_t i = 0; i < d.size(); ++i)
          for (size_t j = i; j < d.size(); ++j) {
            const bool covered = std::any_of(it->second.begin(), it->second.end(), [&](const std::set<std::string>& s) {
              return s.count(d[i]) && s.count(d[j]);
            });
            EXPECT_TRUE(covered) << id << ": " << d[i] << (i == j ? "" : " with " + d[j])
                                 << " is in no program of allPrograms() (drawn as " << spec.key()
                                 << "; settings: " << settingsAsArgs(id, host.currentSettings()) << ")";
          }
        ++checked;
      }
    }
    EXPECT_GT(checked, 0) << id << " reported no active programs";
  }
}

// Each driver caveat's workaround runs where its driver is, and nowhere else: on another renderer
// a lab switch makes no stand-ins and flushes no scenes.
TEST(DriverCaveats, ALabSwitchOnAnotherDriverDoesNoCaveatWork) {
  for (const gl::CaveatEntry& c : gl::kDriverCaveats) {
    EXPECT_FALSE(c.driver.empty() || c.versions.empty() || c.symptom.empty() || c.workaround.empty() ||
                 c.removeWhen.empty())
        << c.name << ": every entry says which driver, the symptom, the workaround and when it can go";
    EXPECT_EQ(&gl::entryOf(c.caveat), &c) << c.name << ": entries in the enum's order";
  }
  const auto switchLabs = [] {
    LabHost host(test::builtinShaders());
    for (const char* id : {"shadows", "surface", "filtering"}) {
      EXPECT_EQ(host.selectLab(id), "");
      host.renderFrame({64, 48}, 0.0f, 1.0f / 60.0f);
    }
  };
  const int textures = gl::workaroundRuns(gl::Caveat::HeldTextures),
            scenes = gl::workaroundRuns(gl::Caveat::HeldScenes);
  gl::pretendRenderer("NVIDIA H100 PCIe/PCIe/SSE2");
  EXPECT_FALSE(gl::applies(gl::Caveat::HeldTextures));
  switchLabs();
  gl::pretendRenderer("");
  EXPECT_EQ(gl::workaroundRuns(gl::Caveat::HeldTextures), textures) << "stand-ins on a driver that needs none";
  EXPECT_EQ(gl::workaroundRuns(gl::Caveat::HeldScenes), scenes);
  if (!gl::rendererIs("llvmpipe")) GTEST_SKIP() << "the workarounds' own runs need llvmpipe";
  switchLabs();
  EXPECT_GE(gl::workaroundRuns(gl::Caveat::HeldTextures), textures + 2) << "one hand-over a switch on llvmpipe";
  EXPECT_GE(gl::workaroundRuns(gl::Caveat::HeldScenes), scenes + 2);
}
