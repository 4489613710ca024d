// The shader folders are a sandbox: a student's #include cannot read a file outside them, whether
// it names the file absolutely, climbs out with "..", or goes through a symbolic link. Every
// refusal names the rule, and nothing of the outside file reaches the output.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "app/shader/preprocessor.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSecret = "SECRET_OF_THE_NEIGHBOUR";

class ShaderSandbox : public ::testing::Test {
 protected:
  void SetUp() override {
    base = fs::temp_directory_path() / ("shadelab_sandbox_" + std::to_string(::getpid()));
    fs::remove_all(base);
    student = base / "class" / "alice";
    builtin = base / "shaders";
    neighbour = base / "class" / "bob";
    write(neighbour / "shading" / "shade.frag", std::string("// ") + kSecret + "\nvoid main() {}\n");
    write(neighbour / "secret.glsl", std::string("float secret() { return 1.0; } // ") + kSecret + "\n");
    write(builtin / "common" / "lighting.glsl", "float lit() { return 1.0; }\n");
    write(builtin / "shading" / "shade.frag", "#version 330 core\n#include \"common/lighting.glsl\"\nvoid main() {}\n");
    fs::create_directories(student / "shading");
  }
  void TearDown() override { fs::remove_all(base); }

  static void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
  }
  // The student's shade.frag with `includeLine` on its second line.
  PreprocessedSource studentFrag(const std::string& includeLine) {
    write(student / "shading" / "shade.frag", "#version 330 core\n" + includeLine + "\nvoid main() {}\n");
    return preprocessShader(ShaderSearchPath({student, builtin}), "shading/shade.frag", {});
  }
  static void expectRefused(const PreprocessedSource& out) {
    EXPECT_FALSE(out.ok());
    EXPECT_NE(out.error.find(kSandboxRule), std::string::npos) << out.error;
    EXPECT_EQ(out.text.find(kSecret), std::string::npos);
    EXPECT_EQ(out.error.find(kSecret), std::string::npos);
    for (auto& f : out.files) EXPECT_EQ(f.string().find("bob"), std::string::npos) << f;
  }

  fs::path base, student, builtin, neighbour;
};

TEST_F(ShaderSandbox, AbsoluteIncludeIsRefused) {
  const PreprocessedSource out = studentFrag("#include \"" + (neighbour / "secret.glsl").string() + "\"");
  expectRefused(out);
  EXPECT_EQ(out.errorLine, 2);
  EXPECT_EQ(out.errorColumn, 11) << "the caret points at the name";
  EXPECT_EQ(out.errorFile, (student / "shading" / "shade.frag").string());
}

TEST_F(ShaderSandbox, SystemFileIsRefused) {
  const PreprocessedSource out = studentFrag("#include \"/etc/os-release\"");
  expectRefused(out);
  EXPECT_EQ(out.error.find("PRETTY_NAME"), std::string::npos);
}

TEST_F(ShaderSandbox, DotDotOutOfTheFolderIsRefused) {
  expectRefused(studentFrag("#include \"../../bob/secret.glsl\""));
  expectRefused(studentFrag("#include \"../../bob/shading/shade.frag\""));
  expectRefused(studentFrag("#include \"common/../../../bob/secret.glsl\""));
  expectRefused(studentFrag("#include \"../../../class/bob/secret.glsl\""));
}

TEST_F(ShaderSandbox, DotDotInsideTheFolderIsFine) {
  write(student / "common" / "mine.glsl", "float mine() { return 2.0; }\n");
  const PreprocessedSource out = studentFrag("#include \"../common/mine.glsl\"");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NE(out.text.find("float mine()"), std::string::npos);
  ASSERT_EQ(out.files.size(), 2u);
  EXPECT_EQ(out.files[1], student / "common" / "mine.glsl");
}

TEST_F(ShaderSandbox, LinkedFileLeavingTheFolderIsRefused) {
  fs::create_directories(student / "common");
  fs::create_symlink(neighbour / "secret.glsl", student / "common" / "lighting.glsl");
  // The link overrides the built-in lighting.glsl by name, but its target is Bob's.
  const PreprocessedSource out = studentFrag("#include \"common/lighting.glsl\"");
  expectRefused(out);
  EXPECT_NE(out.error.find("a link leads out of"), std::string::npos) << out.error;
}

TEST_F(ShaderSandbox, LinkedFolderLeavingTheFolderIsRefused) {
  fs::create_directory_symlink(neighbour, student / "borrowed");
  expectRefused(studentFrag("#include \"borrowed/secret.glsl\""));
  expectRefused(studentFrag("#include \"../borrowed/shading/shade.frag\""));
}

TEST_F(ShaderSandbox, LinkedMainFileLeavingTheFolderIsRefused) {
  fs::create_symlink(neighbour / "shading" / "shade.frag", student / "shading" / "shade.frag");
  const PreprocessedSource out = preprocessShader(ShaderSearchPath({student, builtin}), "shading/shade.frag", {});
  expectRefused(out);
}

TEST_F(ShaderSandbox, LinkInsideTheFolderIsFine) {
  write(student / "common" / "real.glsl", "float real() { return 3.0; }\n");
  fs::create_symlink("real.glsl", student / "common" / "alias.glsl");
  const PreprocessedSource out = studentFrag("#include \"../common/alias.glsl\"");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NE(out.text.find("float real()"), std::string::npos);
}

TEST_F(ShaderSandbox, ARootReachedThroughALinkIsItsOwnFolder) {
  // A student folder that is itself a link (a course's shared drive) is the sandbox it names.
  fs::create_directory_symlink(student, base / "alice_link");
  write(student / "common" / "mine.glsl", "float mine() { return 2.0; }\n");
  write(student / "shading" / "shade.frag", "#version 330 core\n#include \"../common/mine.glsl\"\nvoid main() {}\n");
  const PreprocessedSource out =
      preprocessShader(ShaderSearchPath({base / "alice_link", builtin}), "shading/shade.frag", {});
  EXPECT_TRUE(out.ok()) << out.error;
}

TEST_F(ShaderSandbox, BuiltInIncludesStillResolve) {
  const PreprocessedSource out = studentFrag("#include \"common/lighting.glsl\"");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_EQ(out.files[1], builtin / "common" / "lighting.glsl");
}

TEST_F(ShaderSandbox, FindRefusesNamesThatCannotStayInside) {
  const ShaderSearchPath path({student, builtin});
  for (const char* name : {"", "/etc/passwd", "..", "../x.glsl", "a/../../x.glsl", "shading/../../alice/x"})
    EXPECT_EQ(path.find(name).refused, kSandboxRule) << name;
  EXPECT_EQ(path.find("shading/shade.frag").file, builtin / "shading" / "shade.frag");
  EXPECT_EQ(path.find("./shading/./shade.frag").file, builtin / "shading" / "shade.frag");
}

}  // namespace
