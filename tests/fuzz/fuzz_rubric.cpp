// Rubric JSON (exercises/<lab>/<name>/rubric.json; a course's own rubrics come from its teachers).
#include "app/grade/rubric.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  shadelab::fuzz::writeScratch("exercises/lab/ex/rubric.json", shadelab::fuzz::asText(data, size));
  shadelab::Exercise exercise;
  (void)shadelab::loadExercise(shadelab::fuzz::scratchDir() / "exercises", "lab/ex", exercise);
  return 0;
}
