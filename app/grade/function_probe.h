// The exercised function probed by itself: the student's function and the solution's evaluated on
// the same table of inputs, their results written out as floats, and what the two tables say about
// a mistake nobody listed.
//
// A rubric's "probes" each name a GLSL expression over named inputs ("result":
// "displacedByMap(p, n, uv) - p") and the files that bring the function in with what it needs
// ("include"). The grader generates a fragment shader that reads one row of inputs per pixel from a
// float texture, calls the expression and writes its value: one pixel per input row, one image row
// per draw. The draws are
//   - the base draw of each uniform block ("uniforms": u_scale at 1, then at 0.04, ...),
//   - in the first block, each input replaced by another value of its kind (one at a time): which
//     inputs the result follows,
//   - each of the rubric's input transforms ("u mirrored": uv -> (1 - u, v)): what the solution
//     returns for inputs a student may have turned round,
//   - each quantity of the exercise's inputs ("N.L", "w"): what a result may be scaled by.
// The rows are the inputs a lab passes (drawn at random, the same every time) followed by the edge
// inputs the exercise is about ("edges": w not 1, outside the map, beyond the far plane, ...).
//
// The probe image travels as a frame of its own configuration ("the function by itself"), so the
// child process, the watchdog, the cache and the listed mistakes' frames carry it unchanged; the
// configuration has no checks and never costs a point. GLSL 3.30 and GLSL ES 3.00 alike (the
// preprocessor's dialect): the page probes what the desktop probes.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/measure/image.h"

namespace shadelab {

// How an input's values are drawn.
struct ProbeGenerator {
  enum class Kind { Range, Unit, Hemisphere, Rotation, Values } kind = Kind::Range;
  float low = -1.0f, high = 1.0f;          // Range: every component in [low, high]
  std::string around;                      // Hemisphere: the unit input whose side the vector lies on
  std::vector<std::vector<float>> values;  // Values: taken in turn
};

struct ProbeInput {
  std::string name;  // the GLSL name the result expression uses ("uv")
  std::string type;  // float, vec2, vec3, vec4, mat3
  std::string says;  // in the statement's words ("the texture coordinate uv")
  ProbeGenerator generator;
  bool varyComponents = false;  // each component varied on its own ("clip.x" ... "clip.w")
  int components() const;       // 1 to 4; mat3: 9
};

struct ProbeBlock {    // one setting of the uniforms the function reads
  std::string name;    // for the explanation's tag: "strength" (the first uniform's name by default)
  std::string says;    // "u_scale at 0.04 and u_bias at -0.02"
  std::string varies;  // what it changes from the first block, for "does not change with ...": "the scale u_scale"
  std::vector<std::pair<std::string, std::vector<float>>> uniforms;
};

struct ProbeEdge {         // edge inputs: the lab's rows with some inputs drawn otherwise
  std::string name, says;  // "outside-the-map", "outside the map"
  std::vector<std::pair<std::string, ProbeGenerator>> inputs;
};

struct ProbeTransform {    // an input turned round as a student may have turned it
  std::string name, says;  // "u-mirrored", "u mirrored (1 - u)"
  std::string input, to;   // "uv", "vec2(1.0 - uv.x, uv.y)"
};

struct ProbeQuantity {           // a number of the exercise's inputs a result may be scaled by
  std::string name, says, expr;  // "n-dot-l", "N.L", "dot(N, L)"
};

struct FunctionProbe {
  std::string name;                  // the configuration's name: "the function by itself"
  std::vector<std::string> include;  // files included in order (the student's comes through them)
  std::string prelude;               // GLSL before the includes (what the including file defines first)
  std::string helpers;               // GLSL after them (a wrapper for a function with an out parameter)
  std::vector<std::pair<std::string, std::string>> defines;
  std::string result;      // a float, vec2 or vec3 expression of the inputs
  int size = 1;            // its components
  std::string says;        // "the specular factor"
  std::string components;  // "x, y, z": names of the result's components, for sentences
  std::vector<ProbeInput> inputs;
  std::vector<ProbeBlock> blocks;  // at least one (the first is the base)
  // Sampler uniform -> a texture made for the probe: ramp-r (one channel), ramp-rgb (smooth, not
  // symmetric in u or v), levels (a mip chain whose level k holds k), noise-rgb (16 x 16 unrelated
  // texels, repeating: a read one texel off differs). A name beginning "probe_" is
  // declared by the probe; any other is the included files' own (u_displacement).
  std::vector<std::pair<std::string, std::string>> textures;
  std::vector<ProbeEdge> edges;
  std::vector<ProbeTransform> transforms;
  std::vector<ProbeQuantity> quantities;
  int rows = 128;  // the lab's rows; each edge adds kEdgeRows

  static constexpr int kEdgeRows = 32;
  int totalRows() const { return rows + kEdgeRows * int(edges.size()); }
  // The draws, as image rows from the top: each block's base draw, then (first block) one per
  // varied input or component, one per transform, one per quantity.
  struct Draw {
    enum class Kind { Base, Vary, Transform, Quantity } kind = Kind::Base;
    int block = 0, index = -1;  // Vary: the varied unit; Transform, Quantity: their index
  };
  std::vector<Draw> draws() const;
  // The varied units: each input, or each component of one that varies by component: {input, component or -1}.
  std::vector<std::pair<int, int>> variedUnits() const;
  std::string unitSays(int unit) const;  // "the texture coordinate uv", "clip's x"
  std::string unitName(int unit) const;  // "uv", "clip.x"
};

// Reads one entry of a rubric's "probes". "" or one line naming the key and what is valid.
std::string parseFunctionProbe(const nlohmann::json& j, const std::string& where, FunctionProbe& out);

// Draws the probe in the current GL context with `roots` searched for the files (the student's
// folders first). `image` receives the table (one pixel per row, one image row per draw);
// `errors` the build errors ("" entries never). Returns "" or why the probe could not run at all
// (the rubric's fault: a texture kind it does not know, a float target the driver lacks).
std::string drawFunctionProbe(const FunctionProbe& probe, const std::vector<std::filesystem::path>& roots,
                              ImageF& image, std::vector<std::string>& errors);

// The probe's table traced (grade/trace.h): `text`, the instrumented source of `file`, read in its
// place, and the table drawn once per point at the block's inputs (image row k: point k's
// value on every input row, xyz and its component count in w; w = 0 where it was not reached).
struct ProbeTrace {
  std::string file;  // "common/specular.glsl"
  std::string text;
  int points = 0;
  int block = 0;  // the uniforms' block drawn (one where the two tables differ)
};
std::string drawFunctionTrace(const FunctionProbe& probe, const std::vector<std::filesystem::path>& roots,
                              const ProbeTrace& trace, ImageF& image, std::vector<std::string>& errors);

// What the student's table says against the solution's (and the starter's), strongest first.
struct ProbeFinding {
  // "non-finite", "starter", "transform", "relation", "quantity", "ignores", "uses", "only", "agrees"
  std::string kind;
  std::string key;   // the transform's, quantity's, unit's, block's or edge's name; the relation's kind
  std::string text;  // for the student, in the exercise's words, naming no formula
  double fit = 0.0;  // residual over the student's distance from the solution (0 = exact)
};
// How telling a finding's kind is, for the diagnosis: 0 (non-finite) before the starter's values,
// an input turned round, a relation, an input ignored or used, a quantity, and last where they
// differ (7); -1 for "agrees", which explains nothing.
int findingRank(const std::string& kind);
std::vector<ProbeFinding> analyseProbe(const FunctionProbe& probe, const ImageF& student, const ImageF& solution,
                                       const ImageF* starter);

}  // namespace shadelab
