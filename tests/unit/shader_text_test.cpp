// Preprocessor (#include, defines, #line mapping) and driver log parsing, no GL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>

#include "app/shader/compile_log.h"
#include "app/shader/preprocessor.h"
#include "app/shader/shader_library.h"

using namespace shadelab;
namespace fs = std::filesystem;

class ShaderText : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() / ("shadelab_pp_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "common");
    fs::create_directories(root / "lab");
  }
  void TearDown() override { fs::remove_all(root); }
  void write(const std::string& rel, const std::string& text) { std::ofstream(root / rel) << text; }
  fs::path root;
};

TEST_F(ShaderText, VersionFirstThenDefinesThenLineMappedSource) {
  write("lab/a.frag", "// header comment\n#version 410 core\nvoid main() {}\n");
  auto out = preprocessShader(ShaderSearchPath({root}), "lab/a.frag", {{"MODE_FLAT", "1"}});
  ASSERT_TRUE(out.ok()) << out.error;
  // A fragment stage says so (SHADELAB_FRAGMENT_STAGE), for the files it shares with other stages.
  EXPECT_EQ(out.text.rfind("#version 410 core\n#define MODE_FLAT 1\n#define SHADELAB_FRAGMENT_STAGE 1\n#line 1 0\n", 0),
            0u)
      << out.text;
  // Line 3 of the file ("void main") must still be line 3 after #line 1 0.
  const auto body = out.text.substr(out.text.find("#line 1 0\n") + 10);
  EXPECT_EQ(body, "// header comment\n\nvoid main() {}\n");
}

TEST_F(ShaderText, IncludesAreExpandedOnceWithLineDirectives) {
  write("common/light.glsl", "float light() { return 1.0; }\n");
  write("lab/b.frag",
        "#version 330 core\n#include \"common/light.glsl\"\n#include \"common/light.glsl\"\nvoid main() {}\n");
  auto out = preprocessShader(ShaderSearchPath({root}), "lab/b.frag", {});
  ASSERT_TRUE(out.ok()) << out.error;
  ASSERT_EQ(out.files.size(), 2u);
  EXPECT_EQ(out.files[1], root / "common/light.glsl");
  // The included file's lines carry its index twice: as the source string and as 100000 x index + line.
  EXPECT_NE(out.text.find("#line 100001 1\nfloat light() { return 1.0; }\n#line 3 0\n"), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("float light()"), out.text.rfind("float light()"));  // included once
  EXPECT_NE(out.text.find("#line 4 0\nvoid main"), std::string::npos) << out.text;
}

TEST_F(ShaderText, SiblingIncludeAndStudentOverride) {
  write("lab/helper.glsl", "// built-in helper\n");
  write("lab/c.frag", "#version 330 core\n#include \"helper.glsl\"\n");
  const fs::path student = root / "student";
  fs::create_directories(student / "lab");
  std::ofstream(student / "lab/helper.glsl") << "// student helper\n";
  auto out = preprocessShader(ShaderSearchPath({student, root}), "lab/c.frag", {});
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NE(out.text.find("// student helper"), std::string::npos);
  EXPECT_EQ(out.relPaths[1], "lab/helper.glsl");
}

TEST_F(ShaderText, MissingAndCircularIncludesAreErrorsAtFileLine) {
  write("lab/d.frag", "#version 330 core\n\n#include \"nope.glsl\"\n");
  auto out = preprocessShader(ShaderSearchPath({root}), "lab/d.frag", {});
  EXPECT_EQ(out.error, (root / "lab/d.frag").string() + ":3:11: error: cannot find include \"nope.glsl\"");
  EXPECT_EQ(out.errorLine, 3);
  EXPECT_EQ(out.errorColumn, 11) << "the caret points at the name";
  write("lab/x.glsl", "#include \"y.glsl\"\n");
  write("lab/y.glsl", "#include \"x.glsl\"\n");
  write("lab/e.frag", "#version 330 core\n#include \"x.glsl\"\n");
  out = preprocessShader(ShaderSearchPath({root}), "lab/e.frag", {});
  EXPECT_NE(out.error.find("is circular"), std::string::npos) << out.error;
  out = preprocessShader(ShaderSearchPath({root}), "lab/none.frag", {});
  EXPECT_EQ(out.error, "lab/none.frag: error: shader file not found in the search path");
}

// The ES dialect: "#version 300 es" with precision for every sampler type, and interface blocks
// flattened into varyings named by their members, line for line, #ifdef lines and heads kept out.
TEST_F(ShaderText, TheEsDialectWritesItsVersionAndFlattensInterfaceBlocks) {
  write("lab/a.vert",
        "#version 330 core\n"
        "#ifdef MODE_FLAT\n"
        "out Vertex {\n"
        "#else\n"
        "out Surface {  // to the fragment stage\n"
        "#endif\n"
        "  vec3 worldPos;\n"
        "  UV_INTERP vec2 uv;\n"
        "#ifdef MODE_GOURAUD\n"
        "  flat vec3 colour[2];\n"
        "#endif\n"
        "} vout;\n"
        "void main() { vout.worldPos = vec3(0.0); vout.uv = myvout.uv; }\n");
  setGlslDialect(GlslDialect::Es300);
  auto es = preprocessShader(ShaderSearchPath({root}), "lab/a.vert", {});
  setGlslDialect(GlslDialect::Desktop);
  ASSERT_TRUE(es.ok()) << es.error;
  EXPECT_EQ(es.text.rfind("#version 300 es\n", 0), 0u) << es.text;
  EXPECT_NE(es.text.find("precision highp sampler2DArrayShadow;"), std::string::npos);
  EXPECT_NE(es.text.find("#define SHADELAB_ES 1"), std::string::npos);
  EXPECT_NE(es.text.find("\n#ifdef MODE_FLAT\n\n#else\n\n#endif\n  out vec3 io_worldPos;\n  UV_INTERP out vec2 io_uv;\n"
                         "#ifdef MODE_GOURAUD\n  flat out vec3 io_colour[2];\n#endif\n\n"),
            std::string::npos)
      << es.text;
  EXPECT_NE(es.text.find("io_worldPos = vec3(0.0); io_uv = myvout.uv;"), std::string::npos)
      << "instance.member renamed, a longer name ending in the instance's left alone:\n"
      << es.text;
  EXPECT_EQ(es.text.find("vout."), es.text.find("myvout.") + 2);
  const auto desktop = preprocessShader(ShaderSearchPath({root}), "lab/a.vert", {});
  EXPECT_EQ(desktop.text.rfind("#version 330 core\n", 0), 0u);
  EXPECT_NE(desktop.text.find("} vout;"), std::string::npos) << "the desktop keeps its blocks";
  EXPECT_EQ(
      std::count(es.text.begin(), es.text.end(), '\n') - std::count(desktop.text.begin(), desktop.text.end(), '\n'), 12)
      << "the preamble's lines alone: the source keeps its line numbers";
}

// A line of 100,000 characters inside and after a block: no pattern runs on it (std::regex
// recursed per character and overflowed the stack); the block is still flattened.
TEST(EsFlattening, SurvivesAHugeLine) {
  const std::string huge(100000, ' ');
  const std::string out = flattenInterfaceBlocks("out S {\n" + huge + "vec3 a;\n  vec2 b;\n} v;\n" + huge + "x\n");
  EXPECT_NE(out.find("  out vec2 io_b;"), std::string::npos);
  EXPECT_EQ(out.find("out S"), std::string::npos);
}

// An included file's #extension follows #version, as GLSL requires; one under its own file's #if
// stays with its condition, and every other line keeps its number.
TEST(Preprocessor, ExtensionsOfIncludedFilesFollowTheVersion) {
  const std::string source =
      "#version 330 core\n#line 1 0\nuniform float a;\n#line 1 1\n  #extension GL_ARB_x : require\n"
      "#ifdef FOO\n#extension GL_ARB_y : enable\n#endif\nfloat b;\n";
  const std::string out = hoistExtensions(source);
  EXPECT_EQ(out,
            "#version 330 core\n#extension GL_ARB_x : require\n#line 1 0\nuniform float a;\n#line 1 1\n\n"
            "#ifdef FOO\n#extension GL_ARB_y : enable\n#endif\nfloat b;\n");
  EXPECT_EQ(hoistExtensions("#version 330 core\nfloat c;\n"), "#version 330 core\nfloat c;\n");
  // The #if an include sits in is the including file's: the included file's extension still moves.
  EXPECT_EQ(
      hoistExtensions("#version 330 core\n#line 1 0\n#ifdef BAR\n#line 1 1\n#extension GL_ARB_z : require\n"
                      "#line 3 0\n#endif\n"),
      "#version 330 core\n#extension GL_ARB_z : require\n#line 1 0\n#ifdef BAR\n#line 1 1\n\n#line 3 0\n#endif\n");
}

TEST(CompileLog, MesaNvidiaAmdAndRawLines) {
  const std::vector<fs::path> files = {"shaders/lab/a.frag", "shaders/common/light.glsl"};
  const auto d = parseCompileLog(
      "0:12(5): error: `foo' undeclared\n"
      "1(7) : error C1008: undefined variable \"bar\"\n"
      "ERROR: 0:3: 'baz' : undeclared identifier\n"
      "WARNING: 1:9: unused\n"
      "error: linking failed\n",
      files);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0].format(), "shaders/lab/a.frag:12:5: error: `foo' undeclared");
  EXPECT_EQ(d[1].format(), "shaders/common/light.glsl:7: error: C1008: undefined variable \"bar\"");
  EXPECT_EQ(d[2].format(), "shaders/lab/a.frag:3: error: 'baz' : undeclared identifier");
  EXPECT_FALSE(d[3].isError);
  EXPECT_EQ(d[3].file, "shaders/common/light.glsl");
  EXPECT_EQ(d[4].line, 0);
  EXPECT_EQ(d[4].message, "error: linking failed");  // unparsed: kept verbatim
}

TEST(CompileLog, TheFileIsDecodedFromTheLineWhenTheDriverReportsSourceZero) {
  // Mesa reports every message as source string 0; the preprocessor numbered file 1's lines from 100001.
  const std::vector<std::filesystem::path> files = {"shaders/lab/a.frag", "shaders/common/light.glsl"};
  auto d = parseCompileLog("0:100009(33): error: `oops' undeclared\n", files);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].format(), "shaders/common/light.glsl:9:33: error: `oops' undeclared");
  d = parseCompileLog("1(100009) : error C1008: undefined variable \"oops\"\n", files);  // NVIDIA: both agree
  EXPECT_EQ(d.at(0).format(), "shaders/common/light.glsl:9: error: C1008: undefined variable \"oops\"");
  d = parseCompileLog("0:12(5): error: x\n", files);  // the main file's lines are as they are
  EXPECT_EQ(d.at(0).format(), "shaders/lab/a.frag:12:5: error: x");
}

TEST(CompileLog, UnknownSourceStringIsNamedNotDropped) {
  const auto d = parseCompileLog("7:1(1): error: x\n", {"a.frag"});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "source-string 7");
}

TEST(UniformNames, ASourceMentionsBaseNamesAndMembersAsWholeWords) {
  const std::string src =
      "struct ShadowLight { mat4 viewProj; float layer; };\nuniform ShadowLight u_key;\n"
      "uniform vec2 u_disk[64];\nuniform float u_biasScale;\n";
  EXPECT_TRUE(sourceMentionsUniform(src, "u_key"));
  EXPECT_TRUE(sourceMentionsUniform(src, "u_key.viewProj"));
  EXPECT_TRUE(sourceMentionsUniform(src, "u_disk[3]"));
  EXPECT_FALSE(sourceMentionsUniform(src, "u_key.viewproj"));  // members are checked too
  EXPECT_FALSE(sourceMentionsUniform(src, "u_bias"));          // a prefix of another name is not the name
  EXPECT_FALSE(sourceMentionsUniform(src, "u_dis[0]"));
}
