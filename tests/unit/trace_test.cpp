// The trace without a context: a function read as a tree, instrumented with its taps, and two
// sides' values aligned (grade/trace.h, shader/glsl_syntax.h).
#include "app/grade/trace.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/shader/glsl_syntax.h"

namespace shadelab {
namespace {

const std::string kShader =
    "// a comment with a fake signature: float f(\n"
    "uniform float u_k;\n"
    "float helper(float a) { return a; }\n"
    "vec3 shade(vec3 N, vec3 L, out float e) {\n"
    "  const float k = 2.0 * 0.5;\n"
    "  vec3 h = normalize(L + N);\n"
    "  float s = 0.0, t = dot(N, h);\n"
    "#ifdef OTHER\n"
    "  s = 1.0;\n"
    "#else\n"
    "  for (int i = 0; i < 3; ++i)\n"
    "    s += t > 0.5 ? t * k : -t;\n"
    "#endif\n"
    "  e = s * s;\n"
    "  if (s < 0.0) return vec3(0.0);\n"
    "  return h * helper(s);\n"
    "}\n";

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

const TracePoint* pointNamed(const InstrumentedSource& in, TracePoint::Kind kind, const std::string& name) {
  for (auto& p : in.points)
    if (p.kind == kind && p.name == name) return &p;
  return nullptr;
}

TEST(GlslSyntax, ReadsStatementsAndExpressionsWithTheirLines) {
  glsl::Function f;
  std::string error;
  ASSERT_TRUE(glsl::parseFunction(kShader, "shade", f, error)) << error;
  EXPECT_EQ(f.returnType, "vec3");
  ASSERT_EQ(f.params.size(), 3u);
  EXPECT_EQ(f.params[2].qualifier, "out");
  EXPECT_EQ(f.params[2].type, "float");
  const glsl::Stmt& body = f.stmts[size_t(f.body)];
  ASSERT_EQ(body.kind, glsl::Stmt::Kind::Block);
  // const k, h, s and t, the #ifdef's assignment, the loop, e, the if, the return: both branches read.
  EXPECT_EQ(body.body.size(), 8u);
  const glsl::Stmt& decl = f.stmts[size_t(body.body[2])];
  ASSERT_EQ(decl.declared.size(), 2u);
  EXPECT_EQ(decl.declared[1].name, "t");
  EXPECT_EQ(decl.line, 7);
  EXPECT_EQ(glsl::exprText(kShader, f.exprs[size_t(decl.declared[1].init)]), "dot(N, h)");
  const glsl::Stmt& loop = f.stmts[size_t(body.body[4])];
  ASSERT_EQ(loop.kind, glsl::Stmt::Kind::For);
  const glsl::Stmt& step = f.stmts[size_t(loop.body[0])];
  const glsl::Expr& assign = f.exprs[size_t(step.expr)];
  ASSERT_EQ(assign.kind, glsl::Expr::Kind::Assign);
  EXPECT_EQ(assign.text, "+=");
  EXPECT_EQ(f.exprs[size_t(assign.args[1])].kind, glsl::Expr::Kind::Ternary);
  EXPECT_EQ(f.exprs[size_t(assign.args[1])].line, 12);
}

TEST(GlslSyntax, AnOperationLiesOnItsOperatorsLine) {
  glsl::Function f;
  std::string error;
  ASSERT_TRUE(glsl::parseFunction("float f(float a, float b) {\n  return (a -\n          b)\n         / a;\n}\n", "f",
                                  f, error))
      << error;
  const glsl::Stmt& ret = f.stmts[size_t(f.stmts[size_t(f.body)].body[0])];
  const glsl::Expr& divide = f.exprs[size_t(ret.expr)];
  EXPECT_EQ(divide.text, "/");
  EXPECT_EQ(divide.line, 4);                           // where the division is written
  EXPECT_EQ(f.exprs[size_t(divide.args[0])].line, 2);  // the difference's '-'
}

TEST(GlslSyntax, SaysWhyAFunctionCannotBeRead) {
  glsl::Function f;
  std::string error;
  EXPECT_FALSE(glsl::parseFunction("float g(int x) {\n  switch (x) { default: return 1.0; }\n}\n", "g", f, error));
  EXPECT_NE(error.find("line 2"), std::string::npos) << error;
  EXPECT_FALSE(glsl::parseFunction(kShader, "missing", f, error));
  EXPECT_NE(error.find("no definition of missing()"), std::string::npos);
}

TEST(Trace, EveryValueIsTappedAndTheLinesStayWhereTheyWere) {
  const InstrumentedSource in = instrumentFunctions(kShader, {"shade"});
  ASSERT_TRUE(in.error.empty()) << in.error;
  EXPECT_EQ(count(in.text, "\n"), count(kShader, "\n"));  // compiler errors still point at the student's line
  EXPECT_TRUE(pointNamed(in, TracePoint::Kind::Param, "N"));
  EXPECT_FALSE(pointNamed(in, TracePoint::Kind::Param, "e"));  // an out-parameter has no value on entry
  const TracePoint* h = pointNamed(in, TracePoint::Kind::Declared, "h");
  ASSERT_TRUE(h);
  EXPECT_EQ(h->line, 6);
  const TracePoint* sum = pointNamed(in, TracePoint::Kind::Sub, "L + N");
  ASSERT_TRUE(sum);
  const TracePoint* assigned = pointNamed(in, TracePoint::Kind::Assigned, "s");
  ASSERT_TRUE(assigned);
  EXPECT_EQ(assigned->line, 9);
  EXPECT_EQ(std::count_if(in.points.begin(), in.points.end(),
                          [](const TracePoint& p) { return p.kind == TracePoint::Kind::Returned; }),
            2);
  EXPECT_EQ(std::count_if(in.points.begin(), in.points.end(),
                          [](const TracePoint& p) { return p.kind == TracePoint::Kind::OutParam; }),
            2);  // e, at each return
  // A constant's initialiser stays a constant expression; a loop's header is never touched.
  EXPECT_NE(in.text.find("const float k = 2.0 * 0.5;"), std::string::npos);
  EXPECT_NE(in.text.find("for (int i = 0; i < 3; ++i)"), std::string::npos);
  // The unbraced loop body stays one statement: the assignment and its tap in braces of their own.
  EXPECT_NE(in.text.find("{ s += "), std::string::npos);
  // The other function and the uniform are left as they were.
  EXPECT_NE(in.text.find("float helper(float a) { return a; }"), std::string::npos);
  EXPECT_EQ(std::find(in.literals.begin(), in.literals.end(), 0.5) != in.literals.end(), true);
}

TEST(Trace, QuietLinesAndVariablesAlone) {
  const InstrumentedSource quiet = instrumentFunctions(kShader, {"shade"}, {6});
  EXPECT_FALSE(pointNamed(quiet, TracePoint::Kind::Sub, "L + N"));
  EXPECT_TRUE(pointNamed(quiet, TracePoint::Kind::Declared, "h"));
  const InstrumentedSource alone = instrumentFunctions(kShader, {"shade"}, {}, false);
  EXPECT_FALSE(std::any_of(alone.points.begin(), alone.points.end(),
                           [](const TracePoint& p) { return p.kind == TracePoint::Kind::Sub; }));
  EXPECT_TRUE(pointNamed(alone, TracePoint::Kind::Assigned, "e"));
  const InstrumentedSource none = instrumentFunctions("float f(float x) {\n  return dFdx(x);\n}\n", {"f"});
  EXPECT_NE(none.error.find("derivatives"), std::string::npos);
}

// A side's values, made up: each point a function of the row's input x.
TraceValues side(const std::vector<TracePoint>& points, const std::vector<std::function<float(float)>>& f) {
  TraceValues out;
  out.points = points;
  for (auto& g : f) {
    std::vector<glm::vec4> values;
    for (int r = 0; r < 64; ++r) {
      const float x = -1.0f + 2.0f * float(r) / 63.0f + 0.013f;
      values.push_back({g(x), 0.0f, 0.0f, 1.0f});
    }
    out.values.push_back(values);
  }
  return out;
}

TracePoint at(TracePoint::Kind kind, int line, const std::string& name, std::vector<int> from,
              const std::string& statement = "") {
  TracePoint p;
  p.kind = kind;
  p.line = line;
  p.function = "f";
  p.name = name;
  p.from = std::move(from);
  p.statement = statement;
  return p;
}

TEST(Trace, TheFirstValueThatMatchesNothingIsNamedByItsLine) {
  using K = TracePoint::Kind;
  // The solution: f(x) = 2x + 1.
  const TraceValues solution = side(
      {at(K::Param, 1, "x", {}), at(K::Sub, 2, "2.0 * x", {0}), at(K::Returned, 2, "2.0 * x + 1.0", {1}, "return")},
      {[](float x) { return x; }, [](float x) { return 2 * x; }, [](float x) { return 2 * x + 1; }});
  // The student's: y = 3x on line 2, then y + 1 on line 3.
  const TraceValues student = side({at(K::Param, 1, "x", {}), at(K::Sub, 2, "3.0 * x", {0}, "y"),
                                    at(K::Declared, 2, "y", {1}, "y"), at(K::Returned, 3, "y + 1.0", {2}, "return")},
                                   {[](float x) { return x; }, [](float x) { return 3 * x; },
                                    [](float x) { return 3 * x; }, [](float x) { return 3 * x + 1; }});
  const TraceFinding f = alignTraces(student, solution, {{"x", "the input x"}}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.name, "y");
  EXPECT_EQ(f.tag(), "line:2");
  EXPECT_EQ(f.matching, std::vector<std::string>{"x"});
  EXPECT_EQ(f.text.rfind("Line 2 of f.glsl (`y`): ", 0), 0u) << f.text;
  EXPECT_NE(f.text.find("`x`, which it is made of, matches"), std::string::npos) << f.text;
  EXPECT_EQ(f.text.find("2.0 * x"), std::string::npos) << "the solution's code is never shown: " << f.text;
  // Made of x itself: a relation to x would only restate the code.
  EXPECT_EQ(f.relation, "") << f.relation;
}

TEST(Trace, AResultTurnedRoundIsSaidOfTheResultAndAgreeingCodeHasNoFinding) {
  using K = TracePoint::Kind;
  const TraceValues solution =
      side({at(K::Param, 1, "x", {}), at(K::Sub, 2, "x * x", {0}), at(K::Returned, 2, "x * x", {0}, "return")},
           {[](float x) { return x; }, [](float x) { return x * x; }, [](float x) { return x * x; }});
  // 1 - the solution's result, with every value before it matching.
  const TraceValues turned = side(
      {at(K::Param, 1, "x", {}), at(K::Declared, 2, "sq", {0}, "sq"), at(K::Returned, 3, "1.0 - sq", {1}, "return")},
      {[](float x) { return x; }, [](float x) { return x * x; }, [](float x) { return 1 - x * x; }});
  const TraceFinding f = alignTraces(turned, solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.relation, "one minus the solution's result");
  EXPECT_EQ(f.text.rfind("Line 3 of f.glsl (`1.0 - sq`): ", 0), 0u) << f.text;
  EXPECT_NE(f.text.find("your values up to this line match the solution's"), std::string::npos) << f.text;
  // The same result by another road: nothing to say.
  const TraceValues same =
      side({at(K::Param, 1, "x", {}), at(K::Declared, 2, "a", {0}, "a"), at(K::Returned, 3, "a * a", {1}, "return")},
           {[](float x) { return x; }, [](float x) { return -x; }, [](float x) { return x * x; }});
  EXPECT_FALSE(alignTraces(same, solution, {}, "f.glsl").found);
  const TraceFinding back = traceFindingFromJson(toJson(f));
  EXPECT_EQ(back.text, f.text);
  EXPECT_EQ(back.line, 3);
}

TEST(Trace, WhatNoInputReachesIsGivenAndAConstantTheInputsReachIsNot) {
  using K = TracePoint::Kind;
  const TraceValues solution = side({at(K::Param, 1, "x", {}), at(K::Returned, 2, "x", {0}, "return")},
                                    {[](float x) { return x; }, [](float x) { return x; }});
  // A texture's size on line 2 (no input reaches it) is not where x + half a texel goes wrong.
  const TraceValues shifted =
      side({at(K::Param, 1, "x", {}), at(K::Sub, 2, "textureSize(m, 0).x", {}), at(K::Sub, 3, "x + 0.5 / size", {0, 1}),
            at(K::Returned, 3, "x + 0.5 / size", {2})},
           {[](float x) { return x; }, [](float) { return 64.0f; }, [](float x) { return x + 0.5f / 64.0f; },
            [](float x) { return x + 0.5f / 64.0f; }});
  TraceFinding f = alignTraces(shifted, solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 3);
  // A read the inputs reach that comes out 0 everywhere (a channel the map lacks) is a departure.
  const TraceValues channel =
      side({at(K::Param, 1, "x", {}), at(K::Sub, 2, "texture(m, vec2(x)).g", {0}), at(K::Returned, 3, "x * 0.0", {1})},
           {[](float x) { return x; }, [](float) { return 0.0f; }, [](float) { return 0.0f; }});
  f = alignTraces(channel, solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 2);
}

// Two values side by side in one vector each: (x, 2x) against the solution's (2x, x).
TraceValues pairs(const std::vector<TracePoint>& points, const std::vector<bool>& exchanged) {
  TraceValues out;
  out.points = points;
  for (bool swap : exchanged) {
    std::vector<glm::vec4> values;
    for (int r = 0; r < 64; ++r) {
      const float x = -1.0f + 2.0f * float(r) / 63.0f + 0.013f;
      values.push_back(swap ? glm::vec4(2 * x, x, 0.0f, 2.0f) : glm::vec4(x, 2 * x, 0.0f, 2.0f));
    }
    out.values.push_back(values);
  }
  return out;
}

TEST(Trace, AVectorWithItsComponentsExchangedIsWhereTheValuesPart) {
  using K = TracePoint::Kind;
  const TraceValues solution =
      pairs({at(K::Param, 1, "v", {}), at(K::Returned, 2, "v", {0}, "return")}, {false, false});
  // Every component is one of the solution's, in another place: the vector is not the solution's.
  const TraceValues student =
      pairs({at(K::Param, 1, "v", {}), at(K::Declared, 2, "w", {0}, "w"), at(K::Returned, 3, "w", {1}, "return")},
            {false, true, true});
  const TraceFinding f = alignTraces(student, solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.name, "w");
  EXPECT_NE(f.relation.find("x and y exchanged"), std::string::npos) << f.relation;
}

// A variable the solution also has must hold the solution's values of that name: a value that is
// another of the solution's (the student's p is the solution's q, one step on) has left its role,
// and the line that set it is where the values part, not the first line whose values are no one's.
TEST(Trace, AValueInARoleTheSolutionHasMustHoldThatRolesValues) {
  using K = TracePoint::Kind;
  // The solution: p = x - 0.5, q = p + 1, returns p q.
  const TraceValues solution =
      side({at(K::Param, 1, "x", {}), at(K::Declared, 2, "p", {0}, "p"), at(K::Declared, 3, "q", {1}, "q"),
            at(K::Returned, 4, "p * q", {1, 2}, "return")},
           {[](float x) { return x; }, [](float x) { return x - 0.5f; }, [](float x) { return x + 0.5f; },
            [](float x) { return (x - 0.5f) * (x + 0.5f); }});
  // The student's p = x + 0.5: the solution's q.
  const TraceValues student = side({at(K::Param, 1, "x", {}), at(K::Declared, 2, "p", {0}, "p"),
                                    at(K::Declared, 3, "q", {1}, "q"), at(K::Returned, 4, "p * q", {1, 2}, "return")},
                                   {[](float x) { return x; }, [](float x) { return x + 0.5f; },
                                    [](float x) { return x + 1.5f; }, [](float x) { return (x + 0.5f) * (x + 1.5f); }});
  const TraceFinding f = alignTraces(student, solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 2);
  EXPECT_TRUE(f.isolated());
  EXPECT_NE(f.text.find("`p` does not hold the values of the solution's `p` (the solution computes them "
                        "elsewhere), though `x`, which it is made of, matches"),
            std::string::npos)
      << f.text;
  // A name the solution does not have is matched against all its values, as before: the same
  // function with its p called r is not wrong at r.
  TraceValues renamed = student;
  renamed.points[1].name = renamed.points[1].statement = "r";
  EXPECT_EQ(alignTraces(renamed, solution, {}, "f.glsl").line, 3);
}

// A result with no tap of its own (a matrix) is aligned from the parts it is built of.
TEST(Trace, AMatrixResultIsAlignedFromItsColumns) {
  using K = TracePoint::Kind;
  auto built = [](std::function<float(float)> column) {
    TraceValues t =
        side({at(K::Param, 1, "x", {}), at(K::Declared, 2, "t", {0}, "t"), at(K::Sub, 3, "mat2(t, x)", {1, 0})},
             {[](float x) { return x; }, column, [](float) { return 0.0f; }});
    t.points[2].partOfResult = true;
    for (auto& v : t.values[2]) v.w = 0.0f;  // the matrix's tap writes nothing
    return t;
  };
  const TraceValues solution = built([](float x) { return 2 * x; });
  const TraceFinding f = alignTraces(built([](float x) { return 3 * x; }), solution, {}, "f.glsl");
  ASSERT_TRUE(f.found);
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.name, "t");
  EXPECT_FALSE(alignTraces(solution, solution, {}, "f.glsl").found);
}

}  // namespace
}  // namespace shadelab
