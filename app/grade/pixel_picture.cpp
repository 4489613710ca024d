// The picture of one traced value over the whole frame (grade/pixel_trace.h: drawVariable).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "app/grade/probe_trace.h"
#include "app/grade/traced_draw.h"
#include "app/lab/host_batch.h"
#include "app/util/format.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

std::string drawVariable(const Exercise& ex, size_t configuration, const std::vector<fs::path>& studentDirs,
                         const std::string& name, int line, VariablePicture& out) {
  out = {};
  out.name = name;
  fs::path studentFile;
  if (auto e = checkTraceable(ex, configuration, studentDirs, studentFile); !e.empty()) return e;
  const Configuration& c = ex.configurations[configuration];
  const std::string& file = ex.files.front();
  const HostBatch batch;  // the rounds' and the two sides' hosts share the scene's CPU work
  const std::vector<std::string> functions = tracedFunctions(ex);
  std::vector<TracePoint> points;
  const auto mine = [&](const std::vector<TracePoint>& p) { return pointsNamed(p, name, line); };
  if (auto e = drawPicture(ex, c, functions, readWholeFile(studentFile), withBuiltinShaders(studentDirs), mine,
                           out.yours, points);
      !e.empty())
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

}  // namespace shadelab
