// shadelab inspect: the exercised function at one pixel of a configuration's frame, the student's
// beside the solution's (grade/pixel_trace.h), as text on stdout and with --json as a file; or one
// variable over the whole frame, as a picture.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "app/cli/session.h"
#include "app/grade/pixel_trace.h"
#include "app/grade/rubric.h"
#include "app/util/output_files.h"

namespace shadelab {

int runInspect(const Options& o) {
  if (o.exercise.empty()) return fail("inspect: --exercise LAB/NAME is needed (see `shadelab list`)");
  if (o.shaderDirs.empty()) return fail("inspect: --shaders DIR is needed (the folder with your files)");
  if (!o.pixelGiven && o.variable.empty())
    return fail("inspect: --pixel X,Y is needed (from the frame's top-left), or --variable NAME --out F.png");
  if (!o.variable.empty() && o.out.empty()) return fail("inspect: --variable needs --out F.png, the picture");
  Exercise ex;
  if (auto e = loadExercise(o.exercise, ex); !e.empty()) return fail("inspect: " + e);
  std::string err;
  auto context = createHeadlessContext(o.backend, err);
  if (!context) return fail(err);
  if (!o.variable.empty()) {
    VariablePicture picture;
    if (auto e = drawVariable(ex, size_t(o.config), o.shaderDirs, o.variable, o.line, picture); !e.empty())
      return fail("inspect: " + e);
    if (auto e = writePng(o.out, variableImage(picture)); !e.empty()) return fail("inspect: " + e);
    std::printf("%s: %s\n", o.out.c_str(), describeVariableImage(picture).c_str());
    return 0;
  }
  PixelInspection inspection;
  if (auto e = inspectPixel(ex, size_t(o.config), o.shaderDirs, o.pixel, inspection); !e.empty())
    return fail("inspect: " + e);
  std::printf("%s", formatInspection(inspection).c_str());
  if (!o.json.empty())
    if (auto e = writeTextFile(o.json, toJson(inspection).dump(2) + "\n"); !e.empty()) return fail("inspect: " + e);
  return 0;
}

}  // namespace shadelab
