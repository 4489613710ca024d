// Mutants of a solution: the region a student writes, changed in one place the way students slip
// (an operator or a comparison turned round, a constant changed, a call dropped, two arguments
// exchanged, a component swizzled). `exercise check --mutants` grades each one as a submission: a
// mutant that passes the rubric is a hole in it, unless it draws what the solution draws
// (equivalent, set aside). Pure text work on GLSL, unit-tested without a context.
#pragma once
#include <string>
#include <vector>

namespace shadelab {

struct Mutant {
  std::string
      kind;  // "operator", "comparison", "constant", "call-dropped", "arguments-swapped", "swizzle", "negation-dropped"
  int line = 0;        // 1-based, in the region
  std::string before;  // the line changed, before and after, for the teacher (never shown to a student)
  std::string after;
  std::string from, to;  // the token changed and what it became ("<" -> ">"; a call's or swap's function name)
  std::string text;      // the whole region with the change
};

// Every single change of `region` (comments and preprocessor lines left alone), in order of where
// they occur; at most `most`, spread evenly over the kinds when there are more.
std::vector<Mutant> mutate(const std::string& region, size_t most = 40);

// The slip a mutant makes, in words a student reads beside frames that match it: the kind of change
// and, with `withFix`, what the solution has in its place ("in the solution's terms, a '<' where a
// '>' belongs"). Never the solution's line itself.
std::string describeSlip(const Mutant& m, bool withFix);

}  // namespace shadelab
