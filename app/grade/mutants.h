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
  std::string before;  // the text changed ("a + b" -> the operator's neighbourhood), for the teacher
  std::string after;
  std::string text;  // the whole region with the change
};

// Every single change of `region` (comments and preprocessor lines left alone), in order of where
// they occur; at most `most`, spread evenly over the kinds when there are more.
std::vector<Mutant> mutate(const std::string& region, size_t most = 40);

}  // namespace shadelab
