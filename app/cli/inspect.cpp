// shadelab inspect: the exercised function at one pixel of a configuration's frame, the student's
// beside the solution's (grade/pixel_trace.h), as text on stdout and with --json as a file.
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
  if (!o.pixelGiven) return fail("inspect: --pixel X,Y is needed (from the frame's top-left)");
  Exercise ex;
  if (auto e = loadExercise(o.exercise, ex); !e.empty()) return fail("inspect: " + e);
  std::string err;
  auto context = createHeadlessContext(o.backend, err);
  if (!context) return fail(err);
  PixelInspection inspection;
  if (auto e = inspectPixel(ex, size_t(o.config), o.shaderDirs, o.pixel, inspection); !e.empty())
    return fail("inspect: " + e);
  std::printf("%s", formatInspection(inspection).c_str());
  if (!o.json.empty())
    if (auto e = writeTextFile(o.json, toJson(inspection).dump(2) + "\n"); !e.empty()) return fail("inspect: " + e);
  return 0;
}

}  // namespace shadelab
