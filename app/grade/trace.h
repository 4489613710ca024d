// The student's own code as evidence: their function traced value by value beside the solution's.
//
// 1. Instrument (pure text): every value the function computes is wrapped in a tap,
//    `shadelab_tap(K, e)`, which returns e and, when K is the traced point, writes it out; every
//    parameter on entry, every variable after the statement that sets it, every return and every
//    out-parameter is a point too. Line numbers are kept, so a compile error still points at the
//    student's line. Types are not inferred: the taps are overloaded for GLSL's basic types, and a
//    point the compiler refuses (a struct, a matrix) is dropped by line and the build tried again.
// 2. Draw (grade/function_probe.h, drawFunctionTrace): the probe's table once per point, the
//    student's and the solution's, each point's value per input row.
// 3. Align (here, pure CPU): each of the student's values, per component, against every value the
//    solution computes, its inputs and its constants, over every row both reached. From the
//    student's result down, through the values each point is made of, to the first point whose
//    value matches nothing the solution computes while everything it is made of does: the line
//    where the student's values stop being the solution's. Its sentence says only what the values
//    show (the line, what matches up to there, how the value relates to the solution's result or to
//    an input when a simple relation fits exactly); never the solution's code.
#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json_fwd.hpp>

namespace shadelab {

// One value the instrumented function writes out.
struct TracePoint {
  enum class Kind { Param, Declared, Assigned, Returned, OutParam, Sub };
  Kind kind = Kind::Sub;
  int line = 0;             // 1-based, in the traced file
  std::string function;     // the function it lies in
  std::string name;         // the variable, or the expression as written
  std::string statement;    // Declared / Assigned: the variable; Sub: the variable its statement sets, if any
  std::vector<int> from;    // the points its value is made of (sub-expressions, variables read)
  bool constant = false;    // an expression of literals alone
  bool initialised = true;  // Declared: with a value (`float x;` has none until a call or line sets it)
  // Read straight by a return whose value has no tap (a matrix): a part of the function's result,
  // where the alignment starts as it does at a return.
  bool partOfResult = false;
};

struct InstrumentedSource {
  std::string text;  // the source with its taps; "" when nothing could be traced
  std::vector<TracePoint> points;
  std::vector<double> literals;  // the numbers written in the traced functions
  std::string error;             // why a function could not be traced
};

// The source with `functions` instrumented. Sub-expressions on `quietLines` are not tapped (the
// lines where the compiler refused a tap), and none at all with `subExpressions` false. A function
// that takes derivatives is refused unless `derivativesAllowed` (traced in the lab's own draw,
// grade/pixel_trace.h, rather than on a probe's table, where neighbouring pixels are other rows).
InstrumentedSource instrumentFunctions(const std::string& source, const std::vector<std::string>& functions,
                                       const std::vector<int>& quietLines = {}, bool subExpressions = true,
                                       bool derivativesAllowed = false);

// The GLSL the instrumented source needs before it: the tap overloads, `uniform int shadelab_trace`
// (the point written out, -1 for none) and `vec4 shadelab_traced` (the value: xyz and, in w, its
// component count; w = 0 where the point was not reached).
const std::string& tracePrelude();
// The taps' overloads for GLSL's basic types, each handing its value as a vec4 (xyz, and the
// component count in w) to `write(int k, vec4 v)`, which the including text defines first.
std::string tapOverloads(const std::string& write);

// One side's trace: each point's value on each row of the probe's table.
struct TraceValues {
  std::vector<TracePoint> points;
  std::vector<double> literals;
  std::vector<std::vector<glm::vec4>> values;  // [point][row]
  // The solution's side may add the exercise's quantities (the probe's "quantities": |L + V|,
  // N.L, ...), one number per row: a student's value that is one of them, its reciprocal, its
  // square or its square root is made of what the exercise is about (a half vector normalised by
  // hand), not a departure.
  std::vector<std::vector<float>> quantities;
};

// The lab's own draw is traced in a block of pixels this far each way from the pixel asked for
// (grade/pixel_trace.h): 7 x 7, rows enough for the alignment's 8, at an edge too.
constexpr int kTraceBlockRadius = 3;
constexpr int kTraceBlockSide = 2 * kTraceBlockRadius + 1;

// Where the student's values leave the solution's.
struct TraceFinding {
  bool found = false;
  int line = 0;
  std::string name;  // the variable or the expression at that point
  std::string function;
  std::vector<std::string> matching;  // what it is made of, all matching the solution's values
  std::string relation;               // "" or how it relates ("the solution's result, negated")
  int matchedBefore = 0;              // the student's points before it whose values match
  bool upToHere = false;              // every value on the lines before it matches (and there are some)
  std::string text;                   // the sentence for the student
  // Where the rows came from: the block of the lab's own draw around this pixel (grade/
  // pixel_trace.h), or the probe's table (-1, -1).
  glm::ivec2 pixel{-1};
  bool inDraw() const { return pixel.x >= 0; }
  // Whether the line stands out: what it is made of matches, or everything before it does. A
  // value wrong for a reason none of its operands shows (a count a changed branch grows less
  // often) is where the walk stopped, not where the values part.
  bool isolated() const { return found && (!matching.empty() || upToHere); }
  std::string tag() const { return "line:" + std::to_string(line); }
  // What the rows were, for the sentence's evidence, `configuration` naming where they were drawn.
  std::string evidence(const std::string& configuration) const;
};
// `inputs` names the function's parameters for the student ("the direction to the light L"), by
// the parameter's name.
TraceFinding alignTraces(const TraceValues& student, const TraceValues& solution,
                         const std::vector<std::pair<std::string, std::string>>& inputs, const std::string& file);

// Each of the student's points as alignTraces judges it: reached on enough rows, and its values ones
// the solution computes (the inspector marks each line so).
struct PointAgreement {
  bool reached = false;
  bool matches = false;
};
std::vector<PointAgreement> pointAgreement(const TraceValues& student, const TraceValues& solution);

nlohmann::json toJson(const TraceFinding& f);
TraceFinding traceFindingFromJson(const nlohmann::json& j);

}  // namespace shadelab
