// Command-line options shared by every subcommand.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace shadelab {

struct Options {
  std::string command;               // "" (window), render, sweep, stress, list, check-shaders, compare, grade
  std::string lab;                   // "" = the default (or the preset's)
  std::string scene;                 // "" = the lab's default
  std::vector<std::string> sets;     // --set lab.key=value, in order
  std::vector<std::string> actions;  // --do lab.key, in order, after every --set
  std::vector<std::string> varies;   // --vary key=a,b,c (sweep)
  std::vector<std::filesystem::path> shaderDirs;  // --shaders DIR (student folders, searched first)
  std::string camera;                             // --camera yaw=..,pitch=..
  std::string heightMap;                          // --height-map image.png
  std::string preset;                             // --preset file.json (as written by the app)
  std::string backend = "osmesa";                 // --backend osmesa|egl
  std::string dialect = "desktop";                // check-shaders: --dialect desktop|es
  std::string out;                                // --out file.png (render) or DIR (sweep)
  glm::ivec2 size{960, 540};
  bool sizeGiven = false;
  float time = 0.0f;
  int frames = 5;  // timed frames per configuration (medians)
  int warmup = 2;
  bool measure = false;  // render: measure against the lab's truth too
  std::string exercise;  // grade, inspect: --exercise lab/name
  glm::ivec2 pixel{0};   // inspect: --pixel X,Y (from the frame's top-left)
  bool pixelGiven = false;
  int config = 0;                         // inspect: --config N, the rubric's configuration
  std::string json;                       // inspect: --json FILE
  std::string variable;                   // inspect: --variable NAME, drawn over the whole frame (with --out F.png)
  int line = 0;                           // inspect: --line N, the variable's line (0: any)
  std::vector<std::string> exerciseDirs;  // --exercises DIR (repeatable): course folders, before exercises/
  std::vector<std::string>
      unlisted;  // exercise check: --unlisted DIR (repeatable), mistakes no rubric lists (DIR/LAB/NAME.json)
  std::string
      mutants;  // exercise check: --mutants DIR, the rubric tested by mutation (DIR/LAB/NAME.json: harmless ones)
  std::string function;       // exercise new: --function FILE:NAME, the built-in function the exercise asks for
  std::string format;         // grade: gradescope (one student), moodle or canvas (a class); "": ShadeLab's own only
  bool allExercises = false;  // grade: --all
  double watchdog = 20.0;     // grade: seconds a student's frames may take
  std::filesystem::path classDir;  // grade: --class DIR, one submission per folder or .zip
  int jobs = 1;                    // grade --class: submissions graded at a time
  int shard = 1, shards = 1;       // grade --class: --shard i/n
  std::string cacheDir;            // grade: --cache DIR ("" = the default folder)
  bool noCache = false;            // grade: --no-cache
  bool prepare = false;            // grade: --prepare, fill the solution cache and stop
  int count = 20;                  // random: configurations per lab
  unsigned seed = 1;               // random, soak
  double minutes = 1.0;            // soak
  bool help = false;
  std::vector<std::string> positional;  // compare A.png B.png; grade merge DIR...
};

// Returns "" or a one-line error naming the bad option and what is valid.
std::string parseOptions(int argc, char** argv, Options& out);
// "WxH" into `size`, each side in [minSide, 16384]; returns "" or an error naming `option`.
std::string parseSize(const std::string& option, const std::string& text, glm::ivec2& size, int minSide = 16);
std::string usage();
// "X,Y" with X, Y >= 0 (a pixel) into `pixel`; false when it is not that.
bool parsePixel(const std::string& text, glm::ivec2& pixel);

}  // namespace shadelab
