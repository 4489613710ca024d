// The exercised function traced in the lab's own draw, at the pixel a student points at: their
// function and the solution's instrumented (grade/trace.h) and each drawn in the configuration's
// frame, every tap writing into a shader storage buffer for the fragments of a small block
// around the pixel. So the values are the lab's own: the arguments as the lab passed them there,
// derivatives and all, and a loop's every iteration at the pixel itself. The block's pixels are
// the rows the two sides are aligned on, as the probe's table rows are (alignTraces), and where
// several fragments reach a pixel the nearest one's values are kept (what a depth test keeps).
//
// Needs shader storage buffers in the fragment stage (GL 4.3, or ARB_shader_storage_buffer_object:
// the desktop drivers this lab meets have them; WebGL 2 does not). A function that runs in
// another stage (a displacement in the tessellation stage) reaches no pixel: the result says so.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json_fwd.hpp>

#include "app/grade/rubric.h"
#include "app/grade/trace.h"
#include "app/measure/image.h"

namespace shadelab {

// Whether the current context can trace a pixel; `why` receives why not.
bool pixelTraceSupported(std::string& why);
// `data` (zeros, its size the buffer's) put in a shader storage buffer bound at `binding`, `draw`
// run, and what the shaders wrote read back into it. "" or why not. (pixel_trace_desktop.cpp; the
// page has none: pixel_trace_web.cpp.)
std::string drawIntoStorageBuffer(unsigned binding, std::vector<float>& data, const std::function<void()>& draw);

// One side at the pixel.
struct PixelSide {
  // [point][row]: the block's pixels, row-major from its top-left; each point's last value at
  // that pixel (w = 0 where it was not reached), as alignTraces reads rows.
  TraceValues values;
  int centreRow = -1;                              // the row of the pixel itself
  std::vector<std::vector<glm::vec4>> iterations;  // [point]: every value it took at the pixel, up to kIterations
  std::vector<int> reached;                        // [point]: how many times, at the pixel
  int fragments = 0;         // fragments at the pixel that ran the function (the nearest one's are kept)
  int fragmentsInFrame = 0;  // ... anywhere in the frame
  glm::vec4 colour{0.0f};    // the frame's, at the pixel
  static constexpr int kIterations = 64;
};

struct PixelInspection {
  std::string exercise, configuration, file;
  glm::ivec2 pixel{0};  // image coordinates: x from the left, y from the top
  glm::ivec2 frameSize{0};
  PixelSide student, solution;
  std::vector<PointAgreement> agreement;  // per student point
  TraceFinding departure;                 // the first line whose values leave the solution's
  // What each side returns at the pixel (its last return there), and whether both did.
  glm::vec4 returns{0.0f}, solutionReturns{0.0f};
  bool bothReturned = false;
  bool returnsDiffer() const;
  int firstUnmatched = -1;  // the student's first point (a statement's) whose values are none of the solution's
  std::string note;         // what the values cannot say here ("the function did not run at this pixel")
};

// The student's function (their folders first) and the solution's traced at `pixel` of
// configuration `configuration` of `ex`, in the GL context current here. Returns "" or why the
// pixel cannot be traced (a probe-only configuration, a function that does not build however its
// taps are dropped, a context without storage buffers, a pixel outside the frame).
std::string inspectPixel(const Exercise& ex, size_t configuration,
                         const std::vector<std::filesystem::path>& studentDirs, glm::ivec2 pixel, PixelInspection& out);

// The pixel where two frames of one size differ most (the sum of their colours' differences).
glm::ivec2 mostDifferentPixel(const ImageF& a, const ImageF& b);

// What the grader traces where no probe holds the function: the student's function traced in the
// lab's draw of configuration `configuration` at the pixel where `student` (their frame) differs
// most from `solution`, and the line where their values part (`out.pixel` that pixel; not found
// where nothing parts). Returns "" or why that pixel cannot be traced (the function ran in no
// fragment there, a context without storage buffers, ...).
std::string traceWhereFramesDiffer(const Exercise& ex, size_t configuration,
                                   const std::vector<std::filesystem::path>& studentDirs, const ImageF& student,
                                   const ImageF& solution, TraceFinding& out);

// One variable over the whole frame: each pixel's value of `name` (a variable or parameter of the
// traced function, or "return": what it returns) on `line` (any line if 0), the student's, and the
// solution's where it has a value of that name (its names are its own: where it has none, the
// picture is the student's alone and says so). Each pixel keeps the nearest fragment's last value;
// rgba: xyz, the component count in w (0: not computed there).
struct VariablePicture {
  std::string name;
  ImageF yours, solutions;
  bool solutionHas = false;
};
std::string drawVariable(const Exercise& ex, size_t configuration,
                         const std::vector<std::filesystem::path>& studentDirs, const std::string& name, int line,
                         VariablePicture& out);
// Yours, the solution's and their difference side by side through one colour map (a signed
// scalar diverging around 0, any other scalar black to white, a vector as colours); the sentence
// says which map and its scale.
ImageF variableImage(const VariablePicture& picture);
std::string describeVariableImage(const VariablePicture& picture);

// The lab's own pass at a pixel, with no exercise open: `function` of `file` (by default the lab's
// camera pass, Lab::inspectedPass) traced in the lab's draw on `scene` with `sets` and `camera`
// (as configureHost takes them) at `size`, the shader folders searched first. Its values alone:
// there is no solution to hold them against.
struct LabPixelRequest {
  std::string lab, scene, camera;
  std::vector<std::string> sets;
  std::string file, function;  // "" = the lab's camera pass
  glm::ivec2 size{960, 540};
  glm::ivec2 pixel{0};
};
struct LabInspection {
  LabPixelRequest request;  // with the file and function filled in
  PixelSide side;
  std::string note;
};
std::string inspectLabPixel(const LabPixelRequest& request, const std::vector<std::filesystem::path>& shaderDirs,
                            LabInspection& out);
std::string formatLabInspection(const LabInspection& inspection);

// The inspection's lines: a header, then per traced value its line (`point` its index in
// student.values.points; -1 for the others), the one where the values part marked "> ".
struct InspectionRow {
  std::string text;  // may hold a folded loop's grid on further lines
  int point = -1;
  bool departs = false;
};
std::vector<InspectionRow> inspectionRows(const PixelInspection& inspection);
std::vector<InspectionRow> labInspectionRows(const LabInspection& inspection);
// The inspection as the terminal prints it: the pixel's colours, then each traced line's values,
// yours, with whether the solution computes them there, and the line where they part.
std::string formatInspection(const PixelInspection& inspection);
nlohmann::json toJson(const PixelInspection& inspection);

}  // namespace shadelab
