#include "app/grade/mutants.h"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

namespace shadelab {
namespace {

bool has(const std::vector<Mutant>& ms, const std::string& kind, const std::string& after) {
  return std::any_of(ms.begin(), ms.end(), [&](const Mutant& m) { return m.kind == kind && m.after == after; });
}

TEST(Mutants, EachKindOfSlipOnce) {
  const std::string region =
      "  vec3 h = normalize(L + V);\n"
      "  float s = max(dot(N, h), 0.0);\n"
      "  if (s < 0.5) s = -s;\n"
      "  return mix(a.xy, b.x, s * 2.0);\n";
  const std::vector<Mutant> ms = mutate(region, 1000);
  EXPECT_TRUE(has(ms, "operator", "vec3 h = normalize(L - V);"));
  EXPECT_TRUE(has(ms, "call-dropped", "vec3 h = (L + V);"));
  EXPECT_TRUE(has(ms, "call-dropped", "float s = (dot(N, h));"));
  EXPECT_TRUE(has(ms, "constant", "float s = max(dot(N, h), 1.0);"));
  EXPECT_TRUE(has(ms, "comparison", "if (s > 0.5) s = -s;"));
  EXPECT_TRUE(has(ms, "negation-dropped", "if (s < 0.5) s = s;"));
  EXPECT_TRUE(has(ms, "arguments-swapped", "return mix(b.x, a.xy, s * 2.0);"));
  EXPECT_TRUE(has(ms, "swizzle", "return mix(a.yx, b.x, s * 2.0);"));
  EXPECT_TRUE(has(ms, "swizzle", "return mix(a.xy, b.y, s * 2.0);"));
  EXPECT_TRUE(has(ms, "operator", "return mix(a.xy, b.x, s / 2.0);"));
  EXPECT_TRUE(has(ms, "constant", "return mix(a.xy, b.x, s * 4.0);"));
  // Symmetric calls keep their arguments: max(a, b) exchanged is the same function.
  EXPECT_FALSE(has(ms, "arguments-swapped", "float s = max(0.0, dot(N, h));"));
  for (auto& m : ms) {
    EXPECT_NE(m.text, region) << m.kind;
    EXPECT_GE(m.line, 1);
    EXPECT_LE(m.line, 4);
  }
}

TEST(Mutants, ASlipIsDescribedByItsKindAndNeverByTheSolutionsLine) {
  const std::string region =
      "  float s = max(dot(N, h), 0.25);\n"
      "  if (s < 0.5) s = -s;\n"
      "  return mix(a.xy, b.x, s);\n";
  const std::vector<Mutant> ms = mutate(region, 1000);
  const auto find = [&](const std::string& kind, const std::string& from) {
    const auto it =
        std::find_if(ms.begin(), ms.end(), [&](const Mutant& m) { return m.kind == kind && m.from == from; });
    EXPECT_NE(it, ms.end()) << kind << " " << from;
    return it == ms.end() ? Mutant{} : *it;
  };
  const Mutant comparison = find("comparison", "<");
  EXPECT_EQ(comparison.to, ">");
  EXPECT_EQ(describeSlip(comparison, false), "a comparison turned round, so the test holds where it should fail");
  EXPECT_EQ(describeSlip(comparison, true),
            "a comparison turned round, so the test holds where it should fail (in the solution's terms, a '>' "
            "where a '<' belongs)");
  EXPECT_EQ(describeSlip(find("constant", "0.25"), true),
            "one constant at another value (in the solution's terms, 0.5 where 0.25 belongs)");
  EXPECT_EQ(describeSlip(find("call-dropped", "max"), false), "a call to max left out, its argument used as it is");
  EXPECT_EQ(describeSlip(find("arguments-swapped", "mix"), false), "the first two arguments of mix exchanged");
  EXPECT_EQ(describeSlip(find("negation-dropped", "-"), false),
            "a minus sign left out, so one term has the opposite sign");
  for (auto& m : ms)
    for (bool withFix : {false, true}) {
      const std::string d = describeSlip(m, withFix);
      EXPECT_EQ(d.find(m.before), std::string::npos) << d;  // the solution's line is never shown
      EXPECT_EQ(d.find("dot(N"), std::string::npos) << d;
    }
}

TEST(Mutants, CommentsPreprocessorLinesAndUnaryOperatorsAreLeftAlone) {
  const std::string region =
      "  // a + b * 0.5 in a comment\n"
      "#ifdef ALONG_NORMAL\n"
      "  return -p;  /* 2.0 - 1.0 */\n"
      "#endif\n";
  const std::vector<Mutant> ms = mutate(region, 1000);
  ASSERT_EQ(ms.size(), 1u);  // only the negation, which is not a binary minus
  EXPECT_EQ(ms[0].kind, "negation-dropped");
  EXPECT_EQ(ms[0].line, 3);
}

TEST(Mutants, AtMostSoManySpreadOverTheKinds) {
  std::string region;
  for (int i = 0; i < 30; ++i) region += "  x = x + 1.5 * y.x;\n";
  const std::vector<Mutant> all = mutate(region, 1000), some = mutate(region, 8);
  EXPECT_GT(all.size(), 8u);
  ASSERT_EQ(some.size(), 8u);
  std::set<std::string> kinds;
  for (auto& m : some) kinds.insert(m.kind);
  EXPECT_EQ(kinds.size(), 3u);  // operator, constant, swizzle
  EXPECT_TRUE(
      std::is_sorted(some.begin(), some.end(), [](const Mutant& a, const Mutant& b) { return a.line < b.line; }));
}

}  // namespace
}  // namespace shadelab
