// The headless subcommands. Each returns the process exit code and prints errors as one line
// on stderr.
#pragma once
#include "app/cli/options.h"

namespace shadelab {

int runRender(const Options& o);
int runList(const Options& o);
int runCheckShaders(const Options& o);
int runCheckShadersEs(const Options& o);  // --dialect es (check_shaders_es.cpp)
int runSweep(const Options& o);
int runStress(const Options& o);
int runCompare(const Options& o);     // two PNGs -> rmse, max error; --out writes a diff image
int runGrade(const Options& o);       // exercises/ rubrics against a student's shader folder
int runGradeClass(const Options& o);  // grade --class: every submission in a folder, a gradebook and a class page
int runGradeMerge(const Options& o);  // grade merge: the outputs of --shard runs joined into one
int runRandom(const Options& o);      // random configurations per lab: finite, no GL error, named when black
int runSoak(const Options& o);        // minutes of random use; memory, GL objects and jobs over time
int runExercise(const Options& o);
int runInspect(const Options& o);  // the exercised function traced at one pixel, yours beside the solution's    //
                                   // exercise check [ID | DIR]: an exercise checked before it goes out

}  // namespace shadelab
