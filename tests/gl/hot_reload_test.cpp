// Hot reload through the real file watcher: a student's override is picked up on save (in place
// and by rename), a broken save reports file:line and keeps the last good program, a fix recovers.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <fstream>
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
  EXPECT_EQ(host->shaders().overrideByName(elsewhere / "shade.frag"), "shading/shade.frag");
  host->renderFrame({64, 64});
  EXPECT_EQ(centre(), glm::vec3(0, 1, 1));
  EXPECT_EQ(host->shaders().overrideByName(elsewhere / "nothing.frag"), "");  // no stage of that name
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
