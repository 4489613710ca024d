#include "app/grade/pixel_trace.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include <nlohmann/json.hpp>

#include "app/grade/configuration_frames.h"
#include "app/grade/probe_trace.h"
#include "app/host/configure.h"
#include "app/lab/lab.h"
#include "app/shader/function_parts.h"
#include "app/util/format.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr int kBlockRadius = 3;  // a 7 x 7 block: rows enough for the alignment's 8, at an edge too
constexpr int kBlockSide = 2 * kBlockRadius + 1;
constexpr int kSlots = 4 * kBlockSide * kBlockSide;  // fragments kept: four layers of the block
constexpr int kCentres = 4;                          // fragments at the pixel whose iterations are kept
constexpr int kIterations = PixelSide::kIterations;
constexpr unsigned kBinding = 0;  // every storage block's default binding; no lab uses one

// The buffer's layout (std430): three counters (the block's fragments, the pixel's, the whole
// frame's that ran the function) and a spare word, then vec4s: each slot's
// gl_FragCoord and, per point, {times reached} and the last value; then each centre's slot index
// and, per point, its iterations.
struct Layout {
  int points;
  int slotStride() const { return 1 + 2 * points; }
  int centreBase() const { return kSlots * slotStride(); }
  int centreStride() const { return 1 + points * kIterations; }
  int vec4s() const { return centreBase() + kCentres * centreStride(); }
  size_t bytes() const { return 16 + size_t(vec4s()) * 16; }
};

// The taps of grade/trace.h writing into the buffer, for fragments of the block around
// `fragment` (window coordinates, from the bottom).
std::string pixelPrelude(const Layout& layout, glm::ivec2 fragment) {
  const auto n = [](long v) { return std::to_string(v); };
  return "#extension GL_ARB_shader_storage_buffer_object : require\n"
         "// The pixel trace's taps (grade/pixel_trace.h): each fragment of the block around the pixel takes a\n"
         "// slot of the buffer and writes each point's last value there; at the pixel, every iteration too.\n"
         "// In another stage (a vertex shader that includes the file too) the taps write nothing.\n"
         "#ifdef SHADELAB_FRAGMENT_STAGE\n"
         "layout(std430) buffer shadelab_pixel_trace {\n"
         "  uint shadelab_fragments;\n"
         "  uint shadelab_centres;\n"
         "  uint shadelab_inFrame;\n"
         "  uint shadelab_spare;\n"
         "  vec4 shadelab_data[];\n"
         "};\n"
         "const int shadelab_slotStride = " +
         n(layout.slotStride()) + ";\nconst int shadelab_centreBase = " + n(layout.centreBase()) +
         ";\nconst int shadelab_centreStride = " + n(layout.centreStride()) +
         ";\nconst int shadelab_iterations = " + n(kIterations) + ";\nconst ivec2 shadelab_pixel = ivec2(" +
         n(fragment.x) + ", " + n(fragment.y) +
         ");\n"
         "int shadelab_slot = -2;  // -2: not asked yet; -1: outside the block, or no room\n"
         "int shadelab_centre = -1;\n"
         "bool shadelab_here() {\n"
         "  if (shadelab_slot != -2) return shadelab_slot >= 0;\n"
         "  shadelab_slot = -1;\n"
         "  atomicAdd(shadelab_inFrame, 1u);\n"
         "  ivec2 d = ivec2(gl_FragCoord.xy) - shadelab_pixel;\n"
         "  if (any(greaterThan(abs(d), ivec2(" +
         n(kBlockRadius) +
         ")))) return false;\n"
         "  uint s = atomicAdd(shadelab_fragments, 1u);\n"
         "  if (s >= " +
         n(kSlots) +
         "u) return false;\n"
         "  shadelab_slot = int(s);\n"
         "  shadelab_data[shadelab_slot * shadelab_slotStride] = vec4(gl_FragCoord.xyz, 1.0);\n"
         "  if (d == ivec2(0)) {\n"
         "    uint c = atomicAdd(shadelab_centres, 1u);\n"
         "    if (c < " +
         n(kCentres) +
         "u) {\n"
         "      shadelab_centre = int(c);\n"
         "      shadelab_data[shadelab_centreBase + shadelab_centre * shadelab_centreStride] = vec4(float(s), 0.0, "
         "0.0, "
         "1.0);\n"
         "    }\n"
         "  }\n"
         "  return true;\n"
         "}\n"
         "void shadelab_put(int k, vec4 v) {\n"
         "  if (!shadelab_here()) return;\n"
         "  int at = shadelab_slot * shadelab_slotStride + 1 + 2 * k;\n"
         "  int times = int(shadelab_data[at].x);\n"
         "  shadelab_data[at] = vec4(float(times + 1), 0.0, 0.0, 0.0);\n"
         "  shadelab_data[at + 1] = v;\n"
         "  if (shadelab_centre >= 0 && times < shadelab_iterations)\n"
         "    shadelab_data[shadelab_centreBase + shadelab_centre * shadelab_centreStride + 1 + k * "
         "shadelab_iterations + "
         "times] = v;\n"
         "}\n"
         "#else\n"
         "void shadelab_put(int k, vec4 v) {}\n"
         "#endif\n" +
         tapOverloads("shadelab_put");
}

// A folder removed however the drawing ends.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("shadelab-pixel-" + std::to_string(getpid()));
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// The buffer read back into one side: per block pixel the nearest fragment's values.
void readSide(const std::vector<float>& data, const Layout& layout, glm::ivec2 fragment, PixelSide& side) {
  uint32_t fragments = 0;
  std::memcpy(&fragments, data.data(), sizeof fragments);
  const float* v = data.data() + 4;  // past the counters
  const auto at = [&](int i) { return glm::vec4(v[i * 4], v[i * 4 + 1], v[i * 4 + 2], v[i * 4 + 3]); };
  const int slots = std::min(int(fragments), kSlots);
  const size_t points = size_t(layout.points);
  side.values.values.assign(points, std::vector<glm::vec4>(size_t(kBlockSide * kBlockSide), glm::vec4(0.0f)));
  std::vector<float> nearest(size_t(kBlockSide * kBlockSide), 2.0f);
  std::vector<int> chosen(nearest.size(), -1);
  for (int s = 0; s < slots; ++s) {
    const glm::vec4 coord = at(s * layout.slotStride());
    const glm::ivec2 d = glm::ivec2(int(std::floor(coord.x)), int(std::floor(coord.y))) - fragment;
    if (std::abs(d.x) > kBlockRadius || std::abs(d.y) > kBlockRadius) continue;
    const int row = (kBlockRadius - d.y) * kBlockSide + (d.x + kBlockRadius);  // the block's top row first
    if (coord.z >= nearest[size_t(row)]) continue;
    nearest[size_t(row)] = coord.z;
    chosen[size_t(row)] = s;
  }
  side.centreRow = kBlockRadius * kBlockSide + kBlockRadius;
  for (size_t row = 0; row < chosen.size(); ++row) {
    if (chosen[row] < 0) continue;
    for (size_t k = 0; k < points; ++k) {
      const int base = chosen[row] * layout.slotStride() + 1 + 2 * int(k);
      if (at(base).x > 0.0f) side.values.values[k][row] = at(base + 1);
    }
  }
  side.iterations.assign(points, {});
  side.reached.assign(points, 0);
  uint32_t centres = 0, anywhere = 0;
  std::memcpy(&centres, data.data() + 1, sizeof centres);
  std::memcpy(&anywhere, data.data() + 2, sizeof anywhere);
  side.fragmentsInFrame = int(anywhere);
  side.fragments = int(centres);
  const int centreSlot = chosen[size_t(side.centreRow)];
  for (int c = 0; c < std::min(int(centres), kCentres) && centreSlot >= 0; ++c) {
    const int base = layout.centreBase() + c * layout.centreStride();
    if (int(at(base).x) != centreSlot) continue;  // another layer's fragment
    for (size_t k = 0; k < points; ++k) {
      side.reached[k] = int(at(centreSlot * layout.slotStride() + 1 + 2 * int(k)).x);
      for (int i = 0; i < std::min(side.reached[k], kIterations); ++i)
        side.iterations[k].push_back(at(base + 1 + int(k) * kIterations + i));
    }
  }
}

// Where the taps write: the GLSL before the instrumented text, and the buffer's contents before
// the draw (its size the buffer's), both made for the instrumentation that is being built.
struct TapSink {
  std::function<std::string(const InstrumentedSource&)> prelude;
  std::function<std::vector<float>(const InstrumentedSource&)> initial;
};

// `errors` with every "FILE:LINE:" of `file` moved by `by` lines.
std::vector<std::string> shiftedLines(std::vector<std::string> errors, const std::string& file, int by) {
  const std::string marker = file + ":";
  for (std::string& e : errors)
    for (size_t at = e.find(marker); at != std::string::npos; at = e.find(marker, at + 1)) {
      const size_t digits = at + marker.size();
      size_t end = digits;
      while (end < e.size() && std::isdigit(static_cast<unsigned char>(e[end]))) ++end;
      if (end == digits || end - digits > 9 || end >= e.size() || e[end] != ':') continue;
      e.replace(digits, end - digits, std::to_string(std::max(1, std::stoi(e.substr(digits, end - digits)) + by)));
    }
  return errors;
}

// What a traced draw draws: `file` (the traced one) in a host that `host` makes with the search
// path it is given (an exercise's configuration, or the lab's settings), at `size`.
struct TracedScene {
  std::string file;
  glm::ivec2 size{0};
  std::function<std::unique_ptr<LabHost>(const std::vector<fs::path>& roots, std::string& error)> host;
};

TracedScene exerciseScene(const Exercise& ex, const Configuration& c) {
  return {ex.files.front(), ex.size, [&ex, &c](const std::vector<fs::path>& roots, std::string& error) {
            return configuredHost(roots, ex, c, error);
          }};
}

// `source` instrumented in the place of the scene's file and drawn with `roots` behind it; `data`
// receives what the taps wrote, `frame` the frame.
std::string drawTraced(const TracedScene& scene, const std::vector<std::string>& functions, const std::string& source,
                       const std::vector<fs::path>& roots, const TapSink& sink, InstrumentedSource& built,
                       std::vector<float>& data, ImageF& frame) {
  Scratch scratch;
  std::vector<fs::path> searched{scratch.dir};
  searched.insert(searched.end(), roots.begin(), roots.end());
  const auto draw = [&](const InstrumentedSource& inst, std::vector<std::string>& errors) -> std::string {
    const std::string prelude = sink.prelude(inst);
    if (auto e = writeTextFile((scratch.dir / scene.file).string(), prelude + inst.text); !e.empty()) return e;
    std::string configError;
    const auto host = scene.host(searched, configError);
    if (!configError.empty()) return configError;
    host->shaders().onDiagnostic = [](const Diagnostic&) {};  // the rounds' refused taps are no one's errors
    host->settle();
    data = sink.initial(inst);
    if (auto e = drawIntoStorageBuffer(kBinding, data, [&] { host->renderFrame(scene.size); }); !e.empty()) return e;
    // The errors at the instrumented text's own lines, as the rounds drop taps by them.
    errors = shiftedLines(buildErrors(*host), scene.file, -int(std::count(prelude.begin(), prelude.end(), '\n')));
    frame = host->readImage();
    return {};
  };
  return instrumentAndDraw(scene.file, functions, source, draw, built, true);
}

// One side at the pixel.
std::string drawSide(const TracedScene& scene, const std::vector<std::string>& functions, const std::string& source,
                     const std::vector<fs::path>& roots, glm::ivec2 pixel, PixelSide& out) {
  const glm::ivec2 fragment{pixel.x, scene.size.y - 1 - pixel.y};
  const auto layoutOf = [](const InstrumentedSource& inst) { return Layout{int(inst.points.size())}; };
  const TapSink sink{
      [&](const InstrumentedSource& inst) { return pixelPrelude(layoutOf(inst), fragment); },
      [&](const InstrumentedSource& inst) { return std::vector<float>(layoutOf(inst).bytes() / sizeof(float), 0.0f); }};
  InstrumentedSource built;
  std::vector<float> data;
  ImageF frame;
  if (auto e = drawTraced(scene, functions, source, roots, sink, built, data, frame); !e.empty()) return e;
  if (pixel.x < frame.size.x && pixel.y < frame.size.y) {
    const float* px = frame.at(pixel.x, pixel.y);
    out.colour = {px[0], px[1], px[2], px[3]};
  }
  out.values.points = built.points;
  out.values.literals = built.literals;
  readSide(data, layoutOf(built), fragment, out);
  return {};
}

// The points a picture follows: `name`'s (on `line` if > 0), or every return for "return".
std::vector<int> pointsNamed(const std::vector<TracePoint>& points, const std::string& name, int line) {
  std::vector<int> out;
  for (size_t k = 0; k < points.size(); ++k) {
    const TracePoint& p = points[k];
    const bool matches =
        name == "return" ? p.kind == TracePoint::Kind::Returned : p.kind != TracePoint::Kind::Sub && p.name == name;
    if (matches && (line <= 0 || p.line == line)) out.push_back(int(k));
  }
  return out;
}

// The picture's depth words: one a pixel, rounded up to whole vec4s (std430 starts the pixels'
// vec4 array on 16 bytes).
size_t depthWords(glm::ivec2 size) { return (size_t(size.x) * size_t(size.y) + 3) / 4 * 4; }

// The taps of `wanted` writing each fragment's last value into its pixel of a `size` frame, the
// nearest fragment's kept (an atomic minimum of the depth's bits).
std::string picturePrelude(glm::ivec2 size, const std::vector<int>& wanted) {
  std::string test = "false";
  for (int k : wanted) test += " || k == " + std::to_string(k);
  const std::string w = std::to_string(size.x), h = std::to_string(size.y);
  return "#extension GL_ARB_shader_storage_buffer_object : require\n"
         "// The pixel trace's taps for a picture (grade/pixel_trace.h): the chosen value in every pixel.\n"
         "#ifdef SHADELAB_FRAGMENT_STAGE\n"
         "layout(std430) buffer shadelab_picture {\n"
         "  uint shadelab_depth[" +
         std::to_string(depthWords(size)) +
         "];\n"
         "  vec4 shadelab_pixels[];\n"
         "};\n"
         "void shadelab_put(int k, vec4 v) {\n"
         "  if (!(" +
         test +
         ")) return;\n"
         "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
         "  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, ivec2(" +
         w + ", " + h +
         ")))) return;\n"
         "  int i = p.y * " +
         w +
         " + p.x;\n"
         "  uint z = floatBitsToUint(gl_FragCoord.z);\n"
         "  if (z <= atomicMin(shadelab_depth[i], z)) shadelab_pixels[i] = v;\n"
         "}\n"
         "#else\n"
         "void shadelab_put(int k, vec4 v) {}\n"
         "#endif\n" +
         tapOverloads("shadelab_put");
}

// One side's picture of the points `choose` picks; "" or why not (no such point).
std::string drawPicture(const Exercise& ex, const Configuration& c, const std::vector<std::string>& functions,
                        const std::string& source, const std::vector<fs::path>& roots,
                        const std::function<std::vector<int>(const std::vector<TracePoint>&)>& choose, ImageF& out,
                        std::vector<TracePoint>& points) {
  const size_t pixels = size_t(ex.size.x) * size_t(ex.size.y);
  const size_t depths = depthWords(ex.size);
  const TapSink sink{[&](const InstrumentedSource& inst) { return picturePrelude(ex.size, choose(inst.points)); },
                     [&](const InstrumentedSource&) {
                       std::vector<float> data(depths + pixels * 4, 0.0f);
                       const uint32_t far = 0xffffffffu;  // each depth's bits: nothing drawn yet
                       for (size_t i = 0; i < pixels; ++i) std::memcpy(&data[i], &far, sizeof far);
                       return data;
                     }};
  InstrumentedSource built;
  std::vector<float> data;
  ImageF frame;
  if (auto e = drawTraced(exerciseScene(ex, c), functions, source, roots, sink, built, data, frame); !e.empty())
    return e;
  points = built.points;
  out = ImageF{ex.size, std::vector<float>(pixels * 4, 0.0f)};
  for (int y = 0; y < ex.size.y; ++y)  // the buffer's rows from the bottom, the image's from the top
    std::memcpy(out.at(0, ex.size.y - 1 - y), &data[depths + size_t(y) * size_t(ex.size.x) * 4],
                size_t(ex.size.x) * 4 * sizeof(float));
  return {};
}

std::string vectorText(const glm::vec4& v) {
  const int n = std::clamp(int(v.w), 1, 3);
  std::string out;
  for (int c = 0; c < n; ++c) {
    if (c > 0) out += ' ';
    out += formatSignificant(v[c], 4);
  }
  return n > 1 ? '(' + out + ')' : out;
}

// A point's values at the pixel: one value, or a loop's iterations folded ("25 times: 0 0 1 ...",
// as a grid where the count is a square).
std::string valuesText(const PixelSide& side, size_t k) {
  const std::vector<glm::vec4>& it = side.iterations[k];
  if (side.reached[k] == 0 || it.empty()) return "not reached";
  if (side.reached[k] == 1) return vectorText(it.front());
  std::string out = std::to_string(side.reached[k]) + " times";
  if (std::all_of(it.begin(), it.end(), [&](const glm::vec4& v) { return v == it.front(); }))
    return out + ", each " + vectorText(it.front());
  const int side2 = int(std::lround(std::sqrt(double(it.size()))));
  const bool grid = side2 > 1 && side2 * side2 == int(it.size()) && it.front().w <= 1.0f && side2 <= 8;
  if (grid) {
    out += ", as a " + std::to_string(side2) + " x " + std::to_string(side2) + " grid:";
    for (int r = 0; r < side2; ++r) {
      out += "\n      ";
      for (int col = 0; col < side2; ++col) out += " " + formatSignificant(it[size_t(r * side2 + col)].x, 4);
    }
    return out;
  }
  out += ":";
  constexpr size_t kShown = 8;
  for (size_t i = 0; i < it.size() && i < kShown; ++i) out += " " + vectorText(it[i]);
  if (it.size() > kShown) out += " ... last " + vectorText(it.back());
  return out;
}

std::string kindText(TracePoint::Kind kind) {
  switch (kind) {
    case TracePoint::Kind::Param:
      return "argument";
    case TracePoint::Kind::Declared:
      return "declared";
    case TracePoint::Kind::Assigned:
      return "assigned";
    case TracePoint::Kind::Returned:
      return "returned";
    case TracePoint::Kind::OutParam:
      return "out";
    default:
      return "part";
  }
}

// What a side returns at the pixel: the last value of its last return reached there.
bool returnedAtPixel(const PixelSide& side, glm::vec4& value) {
  bool found = false;
  for (size_t k = 0; k < side.values.points.size(); ++k)
    if (side.values.points[k].kind == TracePoint::Kind::Returned && !side.iterations[k].empty()) {
      value = side.iterations[k].back();
      found = true;
    }
  return found;
}

}  // namespace

bool PixelInspection::returnsDiffer() const {
  if (!bothReturned) return false;
  for (int c = 0; c < std::clamp(int(returns.w), 1, 3); ++c)
    if (!(std::abs(returns[c] - solutionReturns[c]) <= 1e-5f + 3e-4f * std::abs(solutionReturns[c]))) return true;
  return false;
}

std::string inspectPixel(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                         glm::ivec2 pixel, PixelInspection& out) {
  if (configuration >= ex.configurations.size())
    return "--config " + std::to_string(configuration) + ": the exercise has " +
           std::to_string(ex.configurations.size()) + " configurations (0 to " +
           std::to_string(ex.configurations.size() - 1) + ")";
  const Configuration& c = ex.configurations[configuration];
  out = {};
  out.exercise = ex.id;
  out.configuration = c.name;
  out.file = ex.files.front();
  out.pixel = pixel;
  out.frameSize = ex.size;
  if (c.function >= 0) return "configuration '" + c.name + "' is the function by itself: it draws no frame";
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= ex.size.x || pixel.y >= ex.size.y)
    return "--pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) + " is outside the " +
           std::to_string(ex.size.x) + "x" + std::to_string(ex.size.y) + " frame";
  if (std::string why; !pixelTraceSupported(why)) return why;
  const std::string& file = out.file;
  if (file.ends_with(kPartSuffix)) return "a part file is not traced yet";
  const ShaderSearchPath::Lookup found = ShaderSearchPath(studentDirs).find(file);
  if (found.file.empty()) return file + " is not in the student's folders";
  const std::vector<std::string> functions = tracedFunctions(ex);
  std::vector<fs::path> roots = studentDirs;
  roots.push_back(builtinShaderDir());
  const TracedScene scene = exerciseScene(ex, c);
  if (auto e = drawSide(scene, functions, readWholeFile(found.file), roots, pixel, out.student); !e.empty())
    return "your " + file + ": " + e;
  if (auto e = drawSide(scene, functions, labText(ex, file), {builtinShaderDir()}, pixel, out.solution); !e.empty())
    return "the solution's " + file + ": " + e;
  out.agreement = pointAgreement(out.student.values, out.solution.values);
  const bool ranHere = std::any_of(out.student.reached.begin(), out.student.reached.end(), [](int n) { return n > 0; });
  if (!ranHere) {
    out.note = out.student.fragmentsInFrame == 0
                   ? std::string(
                         "your function runs in no fragment of this frame: the lab calls it in another stage "
                         "(per vertex), so no pixel holds its values") +
                         (ex.probes.empty() ? "" : "; `shadelab grade` traces it on its probe")
                   : "your function did not run at this pixel (the background, or a pass this pixel is not drawn by)";
    return {};
  }
  // The alignment's rows: the block's pixels where both sides ran.
  std::vector<std::pair<std::string, std::string>> inputs;
  for (auto& p : out.solution.values.points)
    if (p.kind == TracePoint::Kind::Param) inputs.push_back({p.name, "the argument `" + p.name + "`"});
  out.departure = alignTraces(out.student.values, out.solution.values, inputs, file);
  out.bothReturned = returnedAtPixel(out.student, out.returns) && returnedAtPixel(out.solution, out.solutionReturns);
  for (size_t k = 0; k < out.student.values.points.size() && out.firstUnmatched < 0; ++k)
    if (out.student.values.points[k].kind != TracePoint::Kind::Sub && out.agreement[k].reached &&
        !out.agreement[k].matches)
      out.firstUnmatched = int(k);
  return {};
}

std::string inspectLabPixel(const LabPixelRequest& request, const std::vector<fs::path>& shaderDirs,
                            LabInspection& out) {
  out = {};
  out.request = request;
  LabPixelRequest& r = out.request;
  const std::unique_ptr<Lab> lab = makeLab(r.lab);
  if (!lab) {
    std::string valid;
    for (auto& id : labIds()) valid += (valid.empty() ? "" : ", ") + id;
    return "unknown lab '" + r.lab + "' (valid: " + valid + ")";
  }
  if (r.file.empty()) {
    const Lab::InspectedPass pass = lab->inspectedPass();
    if (pass.file.empty()) return "the " + r.lab + " lab names no pass to inspect";
    r.file = pass.file;
    r.function = pass.function;
  }
  if (r.pixel.x < 0 || r.pixel.y < 0 || r.pixel.x >= r.size.x || r.pixel.y >= r.size.y)
    return "--pixel " + std::to_string(r.pixel.x) + "," + std::to_string(r.pixel.y) + " is outside the " +
           std::to_string(r.size.x) + "x" + std::to_string(r.size.y) + " frame";
  if (std::string why; !pixelTraceSupported(why)) return why;
  std::vector<fs::path> roots = shaderDirs;
  roots.push_back(builtinShaderDir());
  const ShaderSearchPath::Lookup found = ShaderSearchPath(roots).find(r.file);
  if (found.file.empty()) return r.file + " is not in the shader folders";
  const TracedScene scene{r.file, r.size, [&r](const std::vector<fs::path>& searched, std::string& error) {
                            auto host = std::make_unique<LabHost>(ShaderSearchPath(searched), r.lab, r.scene);
                            error = configureHost(*host, r.lab, {}, r.sets, {}, r.camera);
                            return host;
                          }};
  if (auto e = drawSide(scene, {r.function}, readWholeFile(found.file), roots, r.pixel, out.side); !e.empty())
    return r.file + ": " + e;
  if (std::none_of(out.side.reached.begin(), out.side.reached.end(), [](int n) { return n > 0; }))
    out.note = r.function + "() of " + r.file + " did not run at this pixel (the background, or another pass)";
  return {};
}

std::string formatLabInspection(const LabInspection& in) {
  const LabPixelRequest& r = in.request;
  const glm::vec4& c = in.side.colour;
  std::string t = "pixel " + std::to_string(r.pixel.x) + ", " + std::to_string(r.pixel.y) + " of the " + r.lab +
                  " lab (" + std::to_string(r.size.x) + "x" + std::to_string(r.size.y) + "): the frame " +
                  formatSignificant(c.r, 3) + " " + formatSignificant(c.g, 3) + " " + formatSignificant(c.b, 3) + "\n";
  if (!in.note.empty()) return t + in.note + "\n";
  if (in.side.fragments > 1)
    t += std::to_string(in.side.fragments) + " fragments ran it here; the nearest one's values\n";
  t += r.file + ", " + r.function + "():\n";
  for (size_t k = 0; k < in.side.values.points.size(); ++k) {
    const TracePoint& p = in.side.values.points[k];
    // The named values: each variable, argument and return; a statement's parts where they vary.
    if (in.side.reached[k] == 0 || p.constant || !p.initialised) continue;
    if (p.kind == TracePoint::Kind::Sub && in.side.reached[k] < 2) continue;
    const bool named = p.kind == TracePoint::Kind::Param || p.kind == TracePoint::Kind::Returned ||
                       p.kind == TracePoint::Kind::OutParam || p.kind == TracePoint::Kind::Sub;
    t += "  line " + std::to_string(p.line) + (p.kind == TracePoint::Kind::Sub ? "    " : "  ") + p.name +
         (named ? " (" + kindText(p.kind) + ")" : "") + " = " + valuesText(in.side, k) + "\n";
  }
  return t;
}

std::string drawVariable(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                         const std::string& name, int line, VariablePicture& out) {
  if (configuration >= ex.configurations.size())
    return "--config " + std::to_string(configuration) + ": the exercise has " +
           std::to_string(ex.configurations.size()) + " configurations";
  const Configuration& c = ex.configurations[configuration];
  if (c.function >= 0) return "configuration '" + c.name + "' is the function by itself: it draws no frame";
  if (std::string why; !pixelTraceSupported(why)) return why;
  const std::string& file = ex.files.front();
  const ShaderSearchPath::Lookup found = ShaderSearchPath(studentDirs).find(file);
  if (found.file.empty()) return file + " is not in the student's folders";
  out = {};
  out.name = name;
  const std::vector<std::string> functions = tracedFunctions(ex);
  std::vector<fs::path> roots = studentDirs;
  roots.push_back(builtinShaderDir());
  std::vector<TracePoint> points;
  const auto mine = [&](const std::vector<TracePoint>& p) { return pointsNamed(p, name, line); };
  if (auto e = drawPicture(ex, c, functions, readWholeFile(found.file), roots, mine, out.yours, points); !e.empty())
    return "your " + file + ": " + e;
  if (mine(points).empty()) {
    std::string names;
    for (auto& p : points)
      if (p.kind != TracePoint::Kind::Sub && p.kind != TracePoint::Kind::Returned &&
          names.find("`" + p.name + "`") == std::string::npos)
        names += (names.empty() ? "" : ", ") + ("`" + p.name + "`");
    return "no value named '" + name + "'" + (line > 0 ? " on line " + std::to_string(line) : "") + " in your " + file +
           " (valid: " + names + ", return)";
  }
  // The solution's value of the same name, anywhere in its function: its lines are its own.
  const auto theirs = [&](const std::vector<TracePoint>& p) { return pointsNamed(p, name, 0); };
  if (auto e = drawPicture(ex, c, functions, labText(ex, file), {builtinShaderDir()}, theirs, out.solutions, points);
      !e.empty())
    return "the solution's " + file + ": " + e;
  out.solutionHas = !theirs(points).empty();
  return {};
}

namespace {

// What a picture's values span, over both sides: their component count, whether they take both
// signs, and the largest magnitude.
struct PictureRange {
  int components = 1;
  bool signedValues = false;
  float largest = 0.0f;
};

PictureRange rangeOf(const std::vector<const ImageF*>& images) {
  PictureRange r;
  for (const ImageF* image : images)
    for (size_t i = 0; i + 3 < image->rgba.size(); i += 4) {
      const int n = int(image->rgba[i + 3]);
      if (n <= 0) continue;
      r.components = std::max(r.components, std::min(n, 3));
      for (int c = 0; c < std::min(n, 3); ++c) {
        const float v = image->rgba[i + size_t(c)];
        if (!std::isfinite(v)) continue;
        r.signedValues |= v < 0.0f;
        r.largest = std::max(r.largest, std::abs(v));
      }
    }
  return r;
}

constexpr glm::vec3 kNotReached{0.12f, 0.12f, 0.14f};
constexpr glm::vec3 kNonFinite{1.0f, 0.0f, 1.0f};

// One value through the picture's map: a signed scalar blue (negative) to white to red, any other
// scalar black to white, a vector's components as red, green and blue (around mid-grey if signed).
glm::vec3 mapped(const float* v, const PictureRange& r) {
  const int n = int(v[3]);
  if (n <= 0) return kNotReached;
  for (int c = 0; c < std::min(n, 3); ++c)
    if (!std::isfinite(v[c])) return kNonFinite;
  const float scale = r.largest > 0.0f ? 1.0f / r.largest : 1.0f;
  if (r.components == 1) {
    const float t = v[0] * scale;
    if (!r.signedValues) return glm::vec3(t);
    return t >= 0.0f ? glm::mix(glm::vec3(1.0f), glm::vec3(0.85f, 0.1f, 0.1f), t)
                     : glm::mix(glm::vec3(1.0f), glm::vec3(0.1f, 0.25f, 0.85f), -t);
  }
  glm::vec3 out(0.0f);
  for (int c = 0; c < std::min(n, 3); ++c) out[c] = r.signedValues ? 0.5f + 0.5f * v[c] * scale : v[c] * scale;
  return out;
}

// Per pixel, the largest component's difference between the two sides (-1 where either did not
// compute it), and its range.
std::vector<float> differenceOf(const VariablePicture& p, float& lowest, float& largest) {
  const glm::ivec2 size = p.yours.size;
  std::vector<float> out(size_t(size.x) * size_t(size.y), -1.0f);
  lowest = std::numeric_limits<float>::max();
  largest = 0.0f;
  for (int y = 0; p.solutionHas && y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float *a = p.yours.at(x, y), *b = p.solutions.at(x, y);
      if (a[3] <= 0.0f || b[3] <= 0.0f) continue;
      float d = 0.0f;
      for (int c = 0; c < std::clamp(int(a[3]), 1, 3); ++c) d = std::max(d, std::abs(a[c] - b[c]));
      if (!std::isfinite(d)) d = 0.0f;
      out[size_t(y) * size_t(size.x) + size_t(x)] = d;
      lowest = std::min(lowest, d);
      largest = std::max(largest, d);
    }
  return out;
}

}  // namespace

ImageF variableImage(const VariablePicture& p) {
  const glm::ivec2 size = p.yours.size;
  constexpr int kGap = 4;
  const int panels = p.solutionHas ? 3 : 1;
  ImageF out{{size.x * panels + kGap * (panels - 1), size.y}, {}};
  out.rgba.assign(size_t(out.size.x) * size_t(out.size.y) * 4, 1.0f);
  const PictureRange range = p.solutionHas ? rangeOf({&p.yours, &p.solutions}) : rangeOf({&p.yours});
  // The difference: the largest component's, black (none) to white (the largest anywhere).
  float lowestDifference = 0.0f, largestDifference = 0.0f;
  const std::vector<float> difference = differenceOf(p, lowestDifference, largestDifference);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const auto put = [&](int panel, glm::vec3 colour) {
        float* o = out.at(panel * (size.x + kGap) + x, y);
        o[0] = colour.r;
        o[1] = colour.g;
        o[2] = colour.b;
      };
      put(0, mapped(p.yours.at(x, y), range));
      if (!p.solutionHas) continue;
      put(1, mapped(p.solutions.at(x, y), range));
      const float d = difference[size_t(y) * size_t(size.x) + size_t(x)];
      put(2, d < 0.0f ? kNotReached : glm::vec3(largestDifference > 0.0f ? d / largestDifference : 0.0f));
    }
  return out;
}

std::string describeVariableImage(const VariablePicture& p) {
  const PictureRange r = p.solutionHas ? rangeOf({&p.yours, &p.solutions}) : rangeOf({&p.yours});
  const std::string largest = formatSignificant(r.largest, 3);
  std::string map = r.components > 1
                        ? (r.signedValues ? "x, y, z as red, green, blue, mid-grey at 0, full at +-" + largest
                                          : "x, y, z as red, green, blue, full at " + largest)
                        : (r.signedValues ? "blue at -" + largest + ", white at 0, red at " + largest
                                          : "black at 0, white at " + largest);
  std::string difference;
  if (p.solutionHas) {
    float lowest = 0.0f, most = 0.0f;
    differenceOf(p, lowest, most);
    difference = most <= 0.0f ? "their difference (none: black)"
                 : most - lowest <= 1e-4f * most
                     ? "their difference (" + formatSignificant(most, 3) + " wherever both computed it: white)"
                     : "their difference (black at 0, white at " + formatSignificant(most, 3) + ")";
  }
  return "`" + p.name + "` over the frame, " +
         (p.solutionHas ? "yours, the solution's and " + difference
                        : "yours (the solution has no value of that name)") +
         ": " + map + "; dark grey where it was not computed, magenta where it is not finite";
}

std::vector<InspectionRow> inspectionRows(const PixelInspection& in) {
  std::vector<InspectionRow> rows;
  const auto say = [&](std::string text) { rows.push_back({std::move(text), -1, false}); };
  const auto colour = [](const glm::vec4& c) {
    return formatSignificant(c.r, 3) + " " + formatSignificant(c.g, 3) + " " + formatSignificant(c.b, 3);
  };
  say("pixel " + std::to_string(in.pixel.x) + ", " + std::to_string(in.pixel.y) + " of " + quoted(in.configuration) +
      " (" + in.exercise + ", " + std::to_string(in.frameSize.x) + "x" + std::to_string(in.frameSize.y) +
      "): your frame " + colour(in.student.colour) + ", the solution's " + colour(in.solution.colour));
  if (!in.note.empty()) {
    say(in.note);
    return rows;
  }
  if (in.student.fragments > 1)
    say(std::to_string(in.student.fragments) + " fragments ran your function here; the nearest one's values");
  const TracePoint* previous = nullptr;
  for (size_t k = 0; k < in.student.values.points.size(); ++k) {
    const TracePoint& p = in.student.values.points[k];
    // A statement's parts only where they vary at the pixel (a loop's offsets, its taps): once,
    // its variable says what they made; a literal says itself.
    const bool part = p.kind == TracePoint::Kind::Sub;
    const bool departs = in.departure.found && p.line == in.departure.line && p.name == in.departure.name;
    if (part && !departs && (p.constant || in.student.reached[k] < 2)) continue;
    if (!p.initialised && !departs) continue;  // a declaration without a value says nothing
    if (!previous || previous->function != p.function) say(in.file + ", " + p.function + "():");
    previous = &p;
    // A return against the solution's at the pixel; any other value against every value the
    // solution computes around it.
    std::string verdict;
    if (p.kind == TracePoint::Kind::Returned && in.bothReturned && in.student.reached[k] > 0)
      verdict = in.returnsDiffer() ? "  the solution returns " + vectorText(in.solutionReturns) : "  as the solution's";
    else if (in.student.reached[k] > 0 && !in.agreement[k].reached)
      verdict = "  (too few pixels around to compare)";
    else if (in.student.reached[k] > 0)
      verdict = in.agreement[k].matches ? "  a value the solution computes" : "  none of the solution's values";
    const TracePoint::Kind kind = p.kind;
    const bool named = kind == TracePoint::Kind::Param || kind == TracePoint::Kind::Returned ||
                       kind == TracePoint::Kind::OutParam || part;
    std::string values = valuesText(in.student, k);
    const size_t grid = values.find('\n');  // the verdict before a folded loop's grid
    values.insert(grid == std::string::npos ? values.size() : grid, verdict);
    rows.push_back({std::string(departs ? "> " : "  ") + "line " + std::to_string(p.line) + (part ? "    " : "  ") +
                        p.name + (named ? " (" + kindText(kind) + ")" : "") + " = " + values,
                    int(k), departs});
  }
  // Where no line stands out, only what the marks show.
  if (in.departure.found) {
    say(in.departure.text);
  } else if (in.firstUnmatched >= 0) {
    const TracePoint& p = in.student.values.points[size_t(in.firstUnmatched)];
    say("the trace cannot single out the line where your values part from the solution's; the first line whose "
        "values around this pixel are none of the solution's is line " +
        std::to_string(p.line) + " (`" + p.name + "`)");
  } else if (in.returnsDiffer()) {
    say("every value of yours around this pixel is one the solution computes, in some other place: the trace "
        "cannot single out a line");
  } else if (!in.bothReturned) {
    say("every value traced around this pixel is one the solution computes; what your function returns is not "
        "traced (a matrix or a structure), so this does not say that it is the solution's");
  } else {
    say("your values around this pixel are the solution's, and so is what you return here: look where the "
        "frames differ");
  }
  return rows;
}

std::string formatInspection(const PixelInspection& in) {
  std::string t;
  for (auto& row : inspectionRows(in)) t += row.text + "\n";
  return t;
}

nlohmann::json toJson(const PixelInspection& in) {
  const auto vec = [](const glm::vec4& v) {
    nlohmann::json a = nlohmann::json::array();
    for (int c = 0; c < std::clamp(int(v.w), 1, 3); ++c)
      a.push_back(std::isfinite(v[c]) ? nlohmann::json(v[c]) : nullptr);
    return a;
  };
  nlohmann::json lines = nlohmann::json::array();
  for (size_t k = 0; k < in.student.values.points.size(); ++k) {
    const TracePoint& p = in.student.values.points[k];
    nlohmann::json values = nlohmann::json::array();
    for (auto& v : in.student.iterations[k]) values.push_back(vec(v));
    lines.push_back({{"line", p.line},
                     {"function", p.function},
                     {"name", p.name},
                     {"kind", kindText(p.kind)},
                     {"reached", in.student.reached[k]},
                     {"values", values},
                     {"compared", in.agreement[k].reached},
                     {"solution_computes", in.agreement[k].matches}});
  }
  const nlohmann::json solutionResult = in.bothReturned ? vec(in.solutionReturns) : nlohmann::json();
  return {{"exercise", in.exercise},
          {"configuration", in.configuration},
          {"file", in.file},
          {"pixel", {in.pixel.x, in.pixel.y}},
          {"colour",
           {{"yours", vec({glm::vec3(in.student.colour), 3.0f})},
            {"solution", vec({glm::vec3(in.solution.colour), 3.0f})}}},
          {"fragments", in.student.fragments},
          {"lines", lines},
          {"solution_returns", solutionResult},
          {"departure", toJson(in.departure)},
          {"first_unmatched_line",
           in.firstUnmatched >= 0 ? nlohmann::json(in.student.values.points[size_t(in.firstUnmatched)].line) : nullptr},
          {"note", in.note}};
}

}  // namespace shadelab
