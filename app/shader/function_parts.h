// Any function of a built-in shader as an exercise: a student's folder may hold, beside a file
// `F` it does not replace, a part file `F.part` with one or more of F's functions written anew.
// The preprocessor then reads the built-in F with each of those functions swapped for the part's
// (#line directives keep every error at the part file's own line), so an exercise can be one
// function inside a larger shader without copying, or editing, the rest of it.
//
//   shaders/shading/shade.frag            the lab's, untouched
//   my_shaders/shading/shade.frag.part    vec3 reflectLights(...) { ... }   (the student's)
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

inline constexpr std::string_view kPartSuffix = ".part";

// A function definition at the top level of a GLSL source: its name and the lines it spans,
// 1-based and inclusive, from its return type's line to its closing brace's.
struct FunctionSpan {
  std::string name;
  int firstLine = 0, lastLine = 0;
};

// Every top-level function definition of `source`, in order. Comments, preprocessor lines and
// declarations without a body are skipped; braces inside comments do not count.
std::vector<FunctionSpan> findFunctions(std::string_view source);

// The functions of `part` that replace those of `base`: each of the part's functions must be
// defined in the base (an error names the first that is not, and its line), and a part holds no
// #include. "" on success.
std::string matchParts(std::string_view base, std::string_view part, std::vector<FunctionSpan>& baseSpans,
                       std::vector<FunctionSpan>& partSpans);

// The lines of `source` from `span`, joined with '\n' and ending with one.
std::string linesOf(std::string_view source, const FunctionSpan& span);

// The text of a part file holding `names`, as `base` defines them (the solution of an exercise
// whose starter is a part file); "" where the base lacks one of them.
std::string extractPart(std::string_view base, const std::vector<std::string>& names);

}  // namespace shadelab
