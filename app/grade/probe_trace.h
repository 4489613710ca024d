// The exercised function traced on its probe (grade/trace.h), the student's beside the solution's:
// both instrumented, both drawn on the probe's table once per point, then aligned. Runs where the
// probe runs (the grading child, the window's Check, the page), in the GL context current there.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/grade/function_probe.h"
#include "app/grade/rubric.h"
#include "app/grade/trace.h"

namespace shadelab {

// The functions a trace follows: those of the exercise's first file that its starter's TODO region
// lies in (every function of the file for a whole-file starter).
std::vector<std::string> tracedFunctions(const Exercise& ex);

// The rounds a trace is built in: `functions` of `source` (the text of `file`) instrumented and
// handed to `draw`, which builds and draws it and returns "" with the build's errors in `errors`,
// or why it cannot draw at all. A tap the compiler refuses is dropped with the rest of its line's
// and the build tried again; then the variables alone. `built` receives what built.
// `derivativesAllowed`: as instrumentFunctions.
using TraceDraw = std::function<std::string(const InstrumentedSource&, std::vector<std::string>& errors)>;
std::string instrumentAndDraw(const std::string& file, const std::vector<std::string>& functions,
                              const std::string& source, const TraceDraw& draw, InstrumentedSource& built,
                              bool derivativesAllowed = false);

// One side traced: `functions` (tracedFunctions) of `source` (the text of the exercise's first
// file) instrumented and drawn with
// `roots` behind it. A tap the compiler refuses is dropped with the rest of its line's and the
// build tried again; then the variables alone. Returns "" or why it could not be traced.
std::string traceSide(const Exercise& ex, const FunctionProbe& probe, int block,
                      const std::vector<std::string>& functions, const std::string& source,
                      const std::vector<std::filesystem::path>& roots, TraceValues& out);

// The student's function against the solution's on the probe: "" and `out`, or why there is no
// trace (a function outside what the trace reads, a build that fails however its taps are dropped).
// `table` is the student's probe table (drawFunctionProbe), `solution` the solution's: the trace is
// drawn with the first block of uniforms where they differ, and the table's rows of the exercise's
// quantities join the solution's values.
std::string traceOnProbe(const Exercise& ex, const FunctionProbe& probe,
                         const std::vector<std::filesystem::path>& studentRoots, const ImageF& table,
                         const ImageF& solution, TraceFinding& out);

}  // namespace shadelab
