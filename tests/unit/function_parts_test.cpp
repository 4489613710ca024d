// Part files (app/shader/function_parts.h): a folder's F.part replaces the functions of the
// built-in F it defines, and nothing else of F; errors name the part file's own lines.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "app/shader/function_parts.h"
#include "app/shader/preprocessor.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

const char* kBase =
    "// a lab's file\n"                                     // 1
    "uniform float u_k;\n"                                  // 2
    "struct Lit { vec3 a; };  // braces, not a function\n"  // 3
    "float helper(float x) { return x * u_k; }\n"           // 4
    "/* } a brace in a comment */\n"                        // 5
    "#define TWICE(x) (2.0 * (x))\n"                        // 6
    "vec3 shade(vec3 n,\n"                                  // 7
    "           vec3 l) {\n"                                // 8
    "  float d = max(dot(n, l), 0.0);  // { no\n"           // 9
    "  if (d > 0.5) { d = helper(d); }\n"                   // 10
    "  return vec3(d);\n"                                   // 11
    "}\n"                                                   // 12
    "void main() {}\n";                                     // 13

class FunctionParts : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() / ("shadelab_parts_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "lab/lab");
    fs::create_directories(root / "student/lab");
    std::ofstream(root / "lab/lab/a.frag") << "#version 330 core\n" << kBase;
  }
  void TearDown() override { fs::remove_all(root); }
  PreprocessedSource preprocess() {
    return preprocessShader(ShaderSearchPath({root / "student", root / "lab"}), "lab/a.frag", {});
  }
  fs::path root;
};

}  // namespace

TEST(FunctionSpans, TopLevelFunctionsWithTheirLinesAndNothingElse) {
  const std::vector<FunctionSpan> spans = findFunctions(kBase);
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans[0].name, "helper");
  EXPECT_EQ(spans[0].firstLine, 4);
  EXPECT_EQ(spans[0].lastLine, 4);
  EXPECT_EQ(spans[1].name, "shade");
  EXPECT_EQ(spans[1].firstLine, 7);
  EXPECT_EQ(spans[1].lastLine, 12);
  EXPECT_EQ(spans[2].name, "main");
  EXPECT_EQ(extractPart(kBase, {"helper"}), "float helper(float x) { return x * u_k; }\n");
  EXPECT_EQ(extractPart(kBase, {"nope"}), "");
}

TEST_F(FunctionParts, APartReplacesItsFunctionAndKeepsTheRestAndTheLines) {
  std::ofstream(root / "student/lab/a.frag.part") << "// mine\nvec3 shade(vec3 n, vec3 l) {\n  return n;\n}\n";
  const PreprocessedSource out = preprocess();
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NE(out.text.find("  return n;\n"), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("max(dot(n, l), 0.0)"), std::string::npos) << "the lab's body is gone";
  EXPECT_NE(out.text.find("float helper(float x)"), std::string::npos) << "the rest of the file stays";
  ASSERT_EQ(out.relPaths.size(), 2u);
  EXPECT_EQ(out.relPaths[1], "lab/a.frag.part");
  // The part's function at its own lines (source string 1), the lab's file again after it.
  EXPECT_NE(out.text.find("#line 100002 1\nvec3 shade(vec3 n, vec3 l) {\n  return n;\n}\n#line 14 0\n"),
            std::string::npos)
      << out.text;
}

TEST_F(FunctionParts, APartNamingNoFunctionOfTheFileIsAnErrorAtItsLine) {
  std::ofstream(root / "student/lab/a.frag.part") << "\n\nfloat other() { return 1.0; }\n";
  PreprocessedSource out = preprocess();
  EXPECT_EQ(out.errorFile, (root / "student/lab/a.frag.part").string());
  EXPECT_EQ(out.errorLine, 3);
  EXPECT_NE(out.errorMessage.find("'other' is not a function of the file"), std::string::npos) << out.error;
  std::ofstream(root / "student/lab/a.frag.part") << "#include \"x.glsl\"\nfloat helper(float x) { return x; }\n";
  out = preprocess();
  EXPECT_EQ(out.errorLine, 1);
  EXPECT_NE(out.errorMessage.find("no #include"), std::string::npos) << out.error;
  std::ofstream(root / "student/lab/a.frag.part") << "// nothing yet\n";
  out = preprocess();
  EXPECT_NE(out.errorMessage.find("holds none"), std::string::npos) << out.error;
}
