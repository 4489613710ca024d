// Hot reload through the real file watcher: a student's override is picked up on save (in place
// and by rename), a broken save reports file:line and keeps the last good program, a fix recovers.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "gl_test.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

// A fragment shader for the shading lab that paints everything one colour; `extra` lands on line 5.
std::string solidFrag(const char* rgb, const char* extra = "") {
  return std::string("#version 330 core\nin Surface { vec3 worldPos; vec3 normal; vec2 uv; } fin;\n") +
         "out vec4 o_color;\n// line 4\n" + extra + "\nvoid main() { o_color = vec4(" + rgb + ", 1.0); }\n";
}

class HotReload : public ::testing::Test {
 protected:
  void SetUp() override {
    student = fs::temp_directory_path() / ("shadelab_student_" + std::to_string(::getpid()));
    fs::remove_all(student);
    fs::create_directories(student / "shading");
    frag = student / "shading" / "shade.frag";
    save(solidFrag("1.0, 0.0, 0.0"));
    std::vector<fs::path> roots = {student, fs::path(SHADELAB_SOURCE_DIR) / "shaders"};
    host = std::make_unique<LabHost>(ShaderSearchPath(roots));
    host->shaders().onDiagnostic = [this](const Diagnostic& d) { diagnostics.push_back(d); };
    ASSERT_EQ(host->selectScene("cube"), "");
    host->set("shading.mode=phong");
    host->set("shading.textures=off");
  }
  void TearDown() override {
    host.reset();
    fs::remove_all(student);
  }
  void save(const std::string& text) { std::ofstream(frag, std::ios::trunc) << text; }
  void saveByRename(const std::string& text) {
    const fs::path tmp = student / "shading" / ".shade.frag.swp";
    std::ofstream(tmp) << text;
    fs::rename(tmp, frag);
  }
  const Program& program() { return *host->lab().activePrograms().front(); }
  // Renders until the program's build count or failure state changes (at most `limit`).
  bool waitForRebuild(int generation, size_t diagnosticsBefore,
                      std::chrono::milliseconds limit = std::chrono::milliseconds(3000)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      host->renderFrame({64, 64});
      if (program().generation() != generation || diagnostics.size() != diagnosticsBefore) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }
  glm::vec3 centre() {
    const ImageF img = host->readImage();
    const float* p = img.at(32, 32);
    return {p[0], p[1], p[2]};
  }

  fs::path student, frag;
  std::unique_ptr<LabHost> host;
  std::vector<Diagnostic> diagnostics;
};

}  // namespace

TEST_F(HotReload, EditBreakFixCycle) {
  host->renderFrame({64, 64});
  EXPECT_EQ(centre(), glm::vec3(1, 0, 0));  // the student's override, not the built-in shader
  const int gen = program().generation();

  save(solidFrag("0.0, 1.0, 0.0"));
  ASSERT_TRUE(waitForRebuild(gen, diagnostics.size())) << "edit not picked up";
  EXPECT_EQ(centre(), glm::vec3(0, 1, 0));

  const size_t before = diagnostics.size();
  save(solidFrag("0.0, 0.0, 1.0", "float broken = ;"));
  ASSERT_TRUE(waitForRebuild(program().generation(), before)) << "broken save not noticed";
  ASSERT_GT(diagnostics.size(), before);
  EXPECT_EQ(diagnostics[before].file, frag.string());
  EXPECT_EQ(diagnostics[before].line, 5);
  EXPECT_TRUE(program().lastBuildFailed());
  EXPECT_TRUE(program().hasGoodProgram());
  host->renderFrame({64, 64});
  EXPECT_EQ(centre(), glm::vec3(0, 1, 0));  // last good program still on screen

  saveByRename(solidFrag("1.0, 1.0, 0.0"));  // editors that write a temp file and rename it
  ASSERT_TRUE(waitForRebuild(program().generation(), diagnostics.size())) << "rename save not picked up";
  EXPECT_FALSE(program().lastBuildFailed());
  EXPECT_EQ(centre(), glm::vec3(1, 1, 0));
}

TEST_F(HotReload, SavingIdenticalContentDoesNotRecompile) {
  host->renderFrame({64, 64});
  const int gen = program().generation();
  save(solidFrag("1.0, 0.0, 0.0"));  // same bytes, new mtime
  // 0.5 s is over ten times the debounce: a rebuild would have happened by then.
  EXPECT_FALSE(waitForRebuild(gen, diagnostics.size(), std::chrono::milliseconds(500)));
  EXPECT_EQ(program().generation(), gen);
}

TEST_F(HotReload, ADroppedFileReplacesTheStageOfThatName) {
  host->renderFrame({64, 64});
  const fs::path elsewhere = student / "dropped";
  fs::create_directories(elsewhere);
  std::ofstream(elsewhere / "shade.frag") << solidFrag("0.0, 1.0, 1.0");
  EXPECT_EQ(host->shaders().overrideByName(elsewhere / "shade.frag").replaced, "shading/shade.frag");
  host->renderFrame({64, 64});
  EXPECT_EQ(centre(), glm::vec3(0, 1, 1));
  const auto none = host->shaders().overrideByName(elsewhere / "nothing.frag");
  EXPECT_EQ(none.replaced, "");  // no stage of that name
  EXPECT_EQ(none.error, "nothing.frag: no shader of the current lab is named so");
}

TEST_F(HotReload, NeverCompiledProgramDrawsTheFallback) {
  save(solidFrag("0.0", "this is not glsl"));
  host->set("shading.lights=3");  // a new variant, built from the broken file
  host->renderFrame({64, 64});
  EXPECT_FALSE(program().hasGoodProgram());
  const glm::vec3 c = centre();
  EXPECT_TRUE(c == glm::vec3(1, 0, 1) || c == glm::vec3(0, 0, 0)) << "fallback checker expected";
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST_F(HotReload, SwitchingAVariantAndBackWhileBrokenShowsItsLastGoodProgram) {
  host->set("shading.lights=2");
  host->renderFrame({64, 64});
  EXPECT_EQ(centre(), glm::vec3(1, 0, 0));
  const size_t before = diagnostics.size();
  save(solidFrag("0.0, 0.0, 1.0", "float broken = ;"));
  ASSERT_TRUE(waitForRebuild(program().generation(), before)) << "broken save not noticed";
  host->set("shading.lights=3");  // another variant, compiled from the broken file: the fallback
  host->renderFrame({64, 64});
  EXPECT_FALSE(program().hasGoodProgram());
  host->set("shading.lights=2");  // and back: its last good program, not the fallback
  host->renderFrame({64, 64});
  EXPECT_TRUE(program().hasGoodProgram());
  EXPECT_EQ(centre(), glm::vec3(1, 0, 0));
}

TEST_F(HotReload, AMissingIncludeIsShownOnceWithItsCaret) {
  host->renderFrame({64, 64});
  const std::string broken = solidFrag("0.0, 1.0, 0.0", "#include \"common/lightning.glsl\"");
  save(broken);
  const size_t before = diagnostics.size();
  ASSERT_TRUE(waitForRebuild(program().generation(), before));
  for (int lights = 0; lights <= 4; ++lights) {  // five variants read the same broken file
    host->set("shading.lights=" + std::to_string(lights));
    host->renderFrame({64, 64});
  }
  ASSERT_EQ(diagnostics.size(), before + 1) << "one broken include is one message";
  const Diagnostic& d = diagnostics.back();
  EXPECT_EQ(d.format(), frag.string() + ":5:11: error: cannot find include \"common/lightning.glsl\"");
  EXPECT_EQ(d.sourceLine, "#include \"common/lightning.glsl\"") << "the panel's caret needs the line";
}

TEST_F(HotReload, AnErrorInAnIncludedFileNamesThatFileAndLine) {
  // Mesa reports every compile error as source string 0; the file must come through all the same.
  host->renderFrame({64, 64});
  fs::create_directories(student / "common");
  std::ofstream(student / "common" / "tint.glsl") << "// a student's helper\nvec3 tint() {\n  return oops;\n}\n";
  save(solidFrag("tint().r, 0.0, 0.0", "#include \"common/tint.glsl\""));
  const size_t before = diagnostics.size();
  ASSERT_TRUE(waitForRebuild(program().generation(), before));
  ASSERT_GT(diagnostics.size(), before);
  const Diagnostic& d = diagnostics[before];
  EXPECT_EQ(d.file, (student / "common" / "tint.glsl").string());
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.sourceLine, "  return oops;");
}

TEST_F(HotReload, ALinkErrorPointsAtTheDeclarationItNames) {
  // A function declared and called but never defined: the linker names it (and no line), the
  // library finds where it is declared.
  host->renderFrame({64, 64});
  save(solidFrag("helper(), 0.0, 0.0", "float helper();"));
  const size_t before = diagnostics.size();
  ASSERT_TRUE(waitForRebuild(program().generation(), before));
  ASSERT_GT(diagnostics.size(), before);
  const Diagnostic& d = diagnostics[before];
  EXPECT_EQ(d.file, frag.string());
  EXPECT_EQ(d.line, 5);
  EXPECT_EQ(d.column, 7);
  EXPECT_EQ(d.format(), frag.string() + ":5:7: error: unresolved reference to function `helper'");
}

TEST_F(HotReload, AFolderMadeAfterStartIsWatchedAndADeletedOverrideFallsBack) {
  // The student makes common/ only now, with their own lighting: picked up without a restart.
  host->renderFrame({64, 64});
  save(std::string("#version 330 core\n#include \"common/lighting.glsl\"\n") +
       "in Surface { vec3 worldPos; vec3 normal; vec2 uv; } fin;\nout vec4 o_color;\n"
       "void main() { o_color = vec4(u_ka, 0.0, 0.0, 1.0); }\n");
  ASSERT_TRUE(waitForRebuild(program().generation(), diagnostics.size()));
  const int gen = program().generation();
  fs::create_directories(student / "common");
  std::ifstream in(fs::path(SHADELAB_SOURCE_DIR) / "shaders" / "common" / "lighting.glsl");
  std::stringstream text;
  text << in.rdbuf();
  std::ofstream(student / "common" / "lighting.glsl") << "// the student's copy\n" << text.str();
  ASSERT_TRUE(waitForRebuild(gen, diagnostics.size())) << "a file in a folder made after start was not seen";
  EXPECT_EQ(program().files()[1], student / "common" / "lighting.glsl");
  // Deleting the override: back to the built-in file.
  const int gen2 = program().generation();
  fs::remove(frag);
  ASSERT_TRUE(waitForRebuild(gen2, diagnostics.size())) << "deleting the override was not seen";
  const auto& files = program().files();
  EXPECT_NE(std::find(files.begin(), files.end(), fs::path(SHADELAB_SOURCE_DIR) / "shaders" / "shading" / "shade.frag"),
            files.end());
  EXPECT_EQ(std::find(files.begin(), files.end(), frag), files.end());
  host->renderFrame({64, 64});
  EXPECT_GT(centre().g, 0.1f) << "the built-in shading, not the student's red";
}

TEST(ShaderDrops, ADropMatchingTwoFilesIsDecidedByItsPathOrRefused) {
  const fs::path root = fs::temp_directory_path() / ("shadelab_drop_" + std::to_string(::getpid()));
  for (const char* lab : {"alpha", "beta"}) {
    fs::create_directories(root / lab);
    std::ofstream(root / lab / "plain.vert") << "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    std::ofstream(root / lab / "lit.frag") << "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  }
  ShaderLibrary lib(ShaderSearchPath({root}));
  auto a = lib.program({"a", {{GL_VERTEX_SHADER, "alpha/plain.vert"}, {GL_FRAGMENT_SHADER, "alpha/lit.frag"}}, {}});
  auto b = lib.program({"b", {{GL_VERTEX_SHADER, "beta/plain.vert"}, {GL_FRAGMENT_SHADER, "beta/lit.frag"}}, {}});
  fs::create_directories(root / "drops" / "beta");
  std::ofstream(root / "drops" / "lit.frag") << "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.5); }\n";
  std::ofstream(root / "drops" / "beta" / "lit.frag")
      << "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.5); }\n";
  const auto ambiguous = lib.overrideByName(root / "drops" / "lit.frag");
  EXPECT_EQ(ambiguous.replaced, "");
  EXPECT_NE(ambiguous.error.find("lit.frag is ambiguous: it could replace alpha/lit.frag, beta/lit.frag"),
            std::string::npos)
      << ambiguous.error;
  const auto byPath = lib.overrideByName(root / "drops" / "beta" / "lit.frag");
  EXPECT_EQ(byPath.replaced, "beta/lit.frag") << byPath.error;
  EXPECT_EQ(b->files()[1], root / "drops" / "beta" / "lit.frag");
  EXPECT_EQ(a->files()[1], root / "alpha" / "lit.frag");
  fs::remove_all(root);
}
