// The exercised function's draw with its taps (grade/trace.h) writing into a shader storage
// buffer: what the pixel trace (pixel_trace.cpp), the picture of one value (pixel_picture.cpp) and
// their text (pixel_report.cpp) share. Not for use outside grade/pixel_*.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/grade/pixel_trace.h"
#include "app/grade/rubric.h"
#include "app/host/lab_host.h"

namespace shadelab {

// Where the taps write: the GLSL before the instrumented text, and the buffer's contents before
// the draw (its size the buffer's), both made for the instrumentation that is being built.
struct TapSink {
  std::function<std::string(const InstrumentedSource&)> prelude;
  std::function<std::vector<float>(const InstrumentedSource&)> initial;
};

// What a traced draw draws: `file` (the traced one) in a host that `host` makes with the search
// path it is given (an exercise's configuration, or the lab's settings), at `size`.
struct TracedScene {
  std::string file;
  glm::ivec2 size{0};
  std::function<std::unique_ptr<LabHost>(const std::vector<std::filesystem::path>& roots, std::string& error)> host;
};

// An exercise's configuration as a traced draw's scene.
TracedScene exerciseScene(const Exercise& ex, const Configuration& c);

// `source` instrumented in the place of the scene's file and drawn with `roots` behind it (the
// rounds of grade/probe_trace.h: instrumentAndDraw); `data` receives what the taps wrote, `frame`
// the frame.
std::string drawTraced(const TracedScene& scene, const std::vector<std::string>& functions, const std::string& source,
                       const std::vector<std::filesystem::path>& roots, const TapSink& sink, InstrumentedSource& built,
                       std::vector<float>& data, ImageF& frame);

// What inspecting configuration `configuration` of `ex` needs first: a frame of its own, a driver
// with storage buffers and the student's copy of the exercise's file (into `studentFile`). "" or
// why not, in one line.
std::string checkTraceable(const Exercise& ex, size_t configuration,
                           const std::vector<std::filesystem::path>& studentDirs, std::filesystem::path& studentFile);

// `studentDirs`, then the built-in shaders: where the student's side is drawn from.
std::vector<std::filesystem::path> withBuiltinShaders(std::vector<std::filesystem::path> studentDirs);

// A value as the tables write it: "0.32", "(0.5 1)"; `kindText`: "argument", "returned", ...
std::string vectorText(const glm::vec4& v);
std::string kindText(TracePoint::Kind kind);

}  // namespace shadelab
