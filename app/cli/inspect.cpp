// shadelab inspect: the exercised function at one pixel of a configuration's frame, the student's
// beside the solution's (grade/pixel_trace.h), as text on stdout and with --json as a file; or one
// variable over the whole frame, as a picture. With --lab and no exercise, the lab's own pass at
// the pixel (its camera pass's main(), or --function FILE:NAME), its values alone.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "app/cli/session.h"
#include "app/grade/pixel_trace.h"
#include "app/grade/rubric.h"
#include "app/util/output_files.h"

namespace shadelab {

namespace {

// With no exercise: the lab's own pass at the pixel, its named values alone.
int inspectLab(const Options& o) {
  if (!o.pixelGiven) return fail("inspect: --pixel X,Y is needed (from the frame's top-left)");
  LabPixelRequest request{o.lab, o.scene, o.camera, o.sets, {}, {}, o.size, o.pixel};
  if (!o.function.empty()) {
    const size_t colon = o.function.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == o.function.size())
      return fail("inspect: --function '" + o.function + "' is not FILE:NAME (e.g. shadows/lit.frag:main)");
    request.file = o.function.substr(0, colon);
    request.function = o.function.substr(colon + 1);
  }
  std::string err;
  auto context = createHeadlessContext(o.backend, err);
  if (!context) return fail(err);
  LabInspection inspection;
  if (auto e = inspectLabPixel(request, o.shaderDirs, inspection); !e.empty()) return fail("inspect: " + e);
  std::printf("%s", formatLabInspection(inspection).c_str());
  return 0;
}

}  // namespace

int runInspect(const Options& o) {
  if (o.exercise.empty() && !o.lab.empty()) return inspectLab(o);
  if (o.exercise.empty()) return fail("inspect: --exercise LAB/NAME (see `shadelab list`) or --lab L is needed");
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
