#include "app/grade/pixel_trace.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "app/grade/configuration_frames.h"
#include "app/grade/probe_trace.h"
#include "app/grade/traced_draw.h"
#include "app/host/configure.h"
#include "app/lab/host_batch.h"
#include "app/lab/lab.h"
#include "app/shader/function_parts.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr int kBlockRadius = kTraceBlockRadius;
constexpr int kBlockSide = kTraceBlockSide;
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

}  // namespace

TracedScene exerciseScene(const Exercise& ex, const Configuration& c) {
  return {ex.files.front(), ex.size, [&ex, &c](const std::vector<fs::path>& roots, std::string& error) {
            return configuredHost(roots, ex, c, error);
          }};
}

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

namespace {

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

std::vector<fs::path> withBuiltinShaders(std::vector<fs::path> studentDirs) {
  studentDirs.push_back(builtinShaderDir());
  return studentDirs;
}

std::string checkTraceable(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                           fs::path& studentFile) {
  if (configuration >= ex.configurations.size())
    return "--config " + std::to_string(configuration) + ": the exercise has " +
           std::to_string(ex.configurations.size()) + " configurations (0 to " +
           std::to_string(ex.configurations.size() - 1) + ")";
  const Configuration& c = ex.configurations[configuration];
  if (c.function >= 0) return "configuration '" + c.name + "' is the function by itself: it draws no frame";
  if (std::string why; !pixelTraceSupported(why)) return why;
  const std::string& file = ex.files.front();
  if (file.ends_with(kPartSuffix)) return "a part file is not traced yet";
  studentFile = ShaderSearchPath(studentDirs).find(file).file;
  if (studentFile.empty()) return file + " is not in the student's folders";
  return {};
}

bool PixelInspection::returnsDiffer() const {
  if (!bothReturned) return false;
  for (int c = 0; c < std::clamp(int(returns.w), 1, 3); ++c)
    if (!(std::abs(returns[c] - solutionReturns[c]) <= 1e-5f + 3e-4f * std::abs(solutionReturns[c]))) return true;
  return false;
}

std::string inspectPixel(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                         glm::ivec2 pixel, PixelInspection& out) {
  out = {};
  out.exercise = ex.id;
  out.file = ex.files.front();
  out.pixel = pixel;
  out.frameSize = ex.size;
  fs::path studentFile;
  if (auto e = checkTraceable(ex, configuration, studentDirs, studentFile); !e.empty()) return e;
  const Configuration& c = ex.configurations[configuration];
  out.configuration = c.name;
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= ex.size.x || pixel.y >= ex.size.y)
    return "--pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) + " is outside the " +
           std::to_string(ex.size.x) + "x" + std::to_string(ex.size.y) + " frame";
  const std::string& file = out.file;
  const HostBatch batch;  // the rounds' and the two sides' hosts share the scene's CPU work
  const std::vector<std::string> functions = tracedFunctions(ex);
  const TracedScene scene = exerciseScene(ex, c);
  if (auto e =
          drawSide(scene, functions, readWholeFile(studentFile), withBuiltinShaders(studentDirs), pixel, out.student);
      !e.empty())
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

glm::ivec2 mostDifferentPixel(const ImageF& a, const ImageF& b) {
  glm::ivec2 best{0};
  float most = -1.0f;
  for (int y = 0; y < a.size.y && y < b.size.y; ++y)
    for (int x = 0; x < a.size.x && x < b.size.x; ++x) {
      float d = 0.0f;
      for (int c = 0; c < 3; ++c) d += std::abs(a.at(x, y)[c] - b.at(x, y)[c]);
      if (d > most) {
        most = d;
        best = {x, y};
      }
    }
  return best;
}

std::string traceWhereFramesDiffer(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                                   const ImageF& student, const ImageF& solution, TraceFinding& out) {
  out = {};
  if (student.rgba.empty() || student.size != solution.size) return "your frame was not drawn at the solution's size";
  const glm::ivec2 pixel = mostDifferentPixel(student, solution);
  PixelInspection inspection;
  if (auto e = inspectPixel(ex, configuration, studentDirs, pixel, inspection); !e.empty()) return e;
  if (!inspection.note.empty()) return inspection.note;
  out = inspection.departure;
  out.pixel = pixel;
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
  const std::vector<fs::path> roots = withBuiltinShaders(shaderDirs);
  const ShaderSearchPath::Lookup found = ShaderSearchPath(roots).find(r.file);
  const HostBatch batch;  // the rounds' hosts share the scene's CPU work
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

}  // namespace shadelab
