#include "app/cli/options.h"

#include <cstdlib>
#include <filesystem>

#include "app/util/format.h"

namespace shadelab {

std::string usage() {
  return R"(usage: shadelab [COMMAND] [OPTIONS]

commands:
  (none)          open the window (GLFW + Dear ImGui)
  render          render one frame headless:   --out FILE.png (a FILE.json of the settings is written beside it)
  sweep           error against GPU time:      --out DIR [--vary key=a,b,c ...]  (no --vary: the lab's standard sweep)
                  a value may set linked parameters too: --vary filter=hard,pcf:pcf_size=5,pcss
  stress          run the lab's extreme cases; non-zero exit if any fails
  list            labs, their parameters with ranges, and scenes
  check-shaders   compile every program and variant of every lab; non-zero exit on any error
  random          property run: --count N random configurations per lab (every lab, or --lab), drawn from
                  each lab's parameter list with extremes weighted; each must give finite pixels, no GL
                  error, built programs, and a warning if the frame is black; non-zero exit if any fails
  soak            --minutes M of random lab switches, parameters, broken and fixed shader files, meshes
                  loaded and dropped, jobs started and superseded; records resident memory, live GL
                  objects and jobs over time (--out FILE.csv); non-zero exit on growth or a bad frame
  compare A B     RMSE and max error between two images; --out DIFF.png writes an amplified difference
  grade           grade a student's shaders:   --exercise LAB/NAME | --all  --shaders DIR  [--out DIR]
                  one line per check and a score; a Markdown, HTML and JSON report in --out (default
                  out/grades/...); exit 0 at or above the pass mark, 1 below it, 2 if it could not grade
                  a class:  --class DIR (each subfolder or .zip one student) [--jobs N] [--shard i/n]:
                  gradebook.csv, a class page and every student's report; exit 0 when all were graded
  grade merge     join the outputs of --shard runs:  grade merge DIR... --out DIR
  inspect         the exercised function at one pixel of a configuration's frame, traced in the lab's own
                  draw:  --exercise LAB/NAME --shaders DIR --pixel X,Y [--config N] [--json FILE]
                  each line's values there (arguments, variables, a loop's every iteration), yours with
                  whether the solution computes them, and the line where yours leave the solution's;
                  --variable NAME [--line N] --out F.png instead: that variable (or "return") over the
                  whole frame, yours, the solution's and their difference side by side;
                  --lab L [--scene S] [--set ...] [--size WxH] --pixel X,Y [--function FILE:NAME]: the
                  lab's own pass there (its camera pass's main() by default), its values alone
  exercise new LAB/NAME --function FILE:NAME --exercises DIR
                  a new exercise in the course folder DIR on one function of the lab's FILE: the
                  starter (a part file holding the function, its body cut to a TODO region), a
                  rubric with one configuration of the lab's defaults, a check against the
                  solution and one against the truth, and a statement to fill in
  exercise check [ID | DIR]
                  an exercise (an id, an exercise's folder, or a course folder: all of it; none: every
                  exercise) checked before it goes out: its rubric, its starter against the lab's file,
                  and the solution, starter, listed mistakes and correct variants graded as a class;
                  one line per problem, exit 1 if any. --unlisted DIR (repeatable): also grade DIR/LAB/NAME.json,
                  mistakes no rubric lists, each with the explanations that name its cause: how many
                  are named, and a problem for each that passes or is named wrongly. --mutants DIR:
                  also grade mutants of the solution (an operator, comparison or constant changed, a
                  call dropped, arguments exchanged, a component swizzled) and print the mutation
                  score; a problem when under 90 % of those that draw differently fail, or when one
                  passes that DIR/LAB/NAME.json does not list as harmless, with why

options:
  --lab ID            lab to run (see `shadelab list`)
  --scene NAME|FILE   procedural scene name, or a .gltf/.glb/.obj/.off/.ply file
  --height-map IMAGE  the scene's height map (every material's; white = high): relief for a mesh of your own
  --set LAB.KEY=VAL   set a parameter (repeatable)
  --do LAB.KEY        run one of the lab's actions after the --set values, e.g. --do denoise.add_noise
  --preset FILE.json  load lab, scene, params and camera saved by the app or by render
  --size WxH          image size (default 960x540)
  --camera SPEC       yaw=30,pitch=20,distance=4,target=x;y;z,fov=45,near=0.1,far=100
  --time SECONDS      scene time for repeatable frames (default 0)
  --frames N          timed frames per configuration, medians reported (default 5)
  --shaders DIR       search DIR for shader files before shaders/ (repeatable; first wins)
  --backend NAME      headless context: osmesa (default) or egl
  --dialect D         check-shaders: desktop (compiled by the driver, default) or es (GLSL ES 3.00 as the
                      page compiles it, checked by glslangValidator)
  --out PATH          output file or folder
  --measure           measure the frame against the lab's ground truth (render: printed and in the JSON;
                      the window: as if Measure were pressed)
  --exercise ID       grade: the exercise (see `shadelab list`), e.g. shadows/pcf
  --exercises DIR     a course folder of exercises, laid out as exercises/ (repeatable; searched first,
                      before the built-in ones): the window, list, grade, grade --class and exercise check
  --all               grade: every exercise
  --watchdog SECONDS  grade: how long the student's shader may take per configuration (default 20)
  --class DIR         grade: every submission in DIR (a folder or a .zip per student)
  --format F          grade: also write the grades where a course keeps them. One student: gradescope
                      (results.json, Gradescope's autograder results), classroom50 (result.json, Classroom
                      50's classroom50/result/v1, identity from the runner's environment) or prairielearn
                      (results.json, PrairieLearn's external grader results, pictures inline). A class:
                      moodle or canvas (moodle.csv or canvas.csv, the CSV their gradebooks import)
  --jobs N            grade --class: submissions graded at a time (default 1)
  --shard i/n         grade --class: grade the i-th of n deterministic slices (1 <= i <= n), for array jobs
  --cache DIR         grade: keep the solution's frames and truths here (default $SHADELAB_CACHE/solutions
                      or ~/.cache/shadelab/solutions); --no-cache renders them every time
  --prepare           grade: fill that cache for --exercise ID or --all (the solutions' frames, truths,
                      listed mistakes and slips) and stop, as an autograder's image does when it is built
  --count N           random: configurations per lab (default 20)
  --seed N            random, soak: the seed (default 1); the same seed draws the same configurations
  --minutes M         soak: how long (default 1)
  -h, --help          this text

window only:
  --exit-after N      run N frames, then exit (tests)
  --screenshot FILE   save the whole window (UI included) before exiting
  --present           start in presentation mode: the viewport fills the window (F11 toggles, Esc leaves)
  --window-size WxH   the window's size at start (default 1280x800)
  --exercise ID       open the Exercises section on this exercise (with --check: press its Check)
  --ui-scale S        text and widgets S times larger, 0.5..4, for projectors (default: the monitor's scale)
  --cycle-labs        switch to every lab in turn while running
  --auto-measure      start with Auto measure on
  --soak M            random use of the window for M minutes (as `soak`), then exit 0, or 1 on a problem
  --soak-seed N       the soak's seed (default 1)
)";
}

std::string parseSize(const std::string& option, const std::string& text, glm::ivec2& size, int minSide) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < minSide || h < minSide ||
      w > 16384 || h > 16384)
    return option + ": '" + text + "' is not WxH with " + std::to_string(minSide) + " <= W,H <= 16384 (e.g. 1280x720)";
  size = {w, h};
  return {};
}

bool parsePixel(const std::string& text, glm::ivec2& pixel) {
  int x = 0, y = 0;
  char comma = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &x, &comma, &y, &extra) != 3 || comma != ',' || x < 0 || y < 0)
    return false;
  pixel = {x, y};
  return true;
}

std::string parseOptions(int argc, char** argv, Options& o) {
  static const char* kCommands[] = {"render", "sweep",  "stress", "list",     "check-shaders", "compare",
                                    "grade",  "random", "soak",   "exercise", "inspect"};
  int i = 1;
  if (i < argc && argv[i][0] != '-') {
    o.command = argv[i++];
    bool known = false;
    for (auto c : kCommands) known |= o.command == c;
    if (!known)
      return "unknown command '" + o.command +
             "' (valid: render, sweep, stress, list, check-shaders, compare, grade, random, soak, exercise, "
             "inspect)";
  }
  for (; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      continue;
    }
    if (arg == "--measure") {
      o.measure = true;
      continue;
    }
    if (arg == "--all") {
      o.allExercises = true;
      continue;
    }
    if (arg == "--no-cache") {
      o.noCache = true;
      continue;
    }
    if (arg == "--prepare") {
      o.prepare = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0) {
      const bool merge = o.command == "grade" && (!o.positional.empty() ? o.positional[0] == "merge" : arg == "merge");
      if (o.command != "compare" && o.command != "exercise" && !merge)
        return "unexpected argument '" + arg + "' (see --help)";
      o.positional.push_back(arg);
      continue;
    }
    if (i + 1 >= argc) return arg + ": missing value";
    const std::string v = argv[++i];
    if (arg == "--lab")
      o.lab = v;
    else if (arg == "--scene")
      o.scene = v;
    else if (arg == "--height-map")
      o.heightMap = v;
    else if (arg == "--set")
      o.sets.push_back(v);
    else if (arg == "--do")
      o.actions.push_back(v);
    else if (arg == "--vary")
      o.varies.push_back(v);
    else if (arg == "--shaders")
      o.shaderDirs.emplace_back(v);
    else if (arg == "--camera")
      o.camera = v;
    else if (arg == "--preset")
      o.preset = v;
    else if (arg == "--backend")
      o.backend = v;
    else if (arg == "--dialect") {
      if (v != "desktop" && v != "es") return "--dialect: invalid value '" + v + "' (valid: desktop, es)";
      o.dialect = v;
    } else if (arg == "--out")
      o.out = v;
    else if (arg == "--exercise")
      o.exercise = v;
    else if (arg == "--json")
      o.json = v;
    else if (arg == "--variable")
      o.variable = v;
    else if (arg == "--line") {
      long n = 0;
      if (!parseWholeNumber(v, 1, 100000, n)) return "--line: '" + v + "' is not a line number (1 or more)";
      o.line = int(n);
    } else if (arg == "--pixel") {
      if (!parsePixel(v, o.pixel))
        return "--pixel: '" + v + "' is not X,Y with X, Y >= 0 (from the frame's top-left, e.g. 160,120)";
      o.pixelGiven = true;
    } else if (arg == "--config") {
      long n = 0;
      if (!parseWholeNumber(v, 0, 1000, n)) return "--config: '" + v + "' is not a whole number in [0, 1000]";
      o.config = int(n);
    } else if (arg == "--exercises") {
      std::error_code ec;
      if (o.command != "exercise" && !std::filesystem::is_directory(v, ec))  // `exercise new` may make it
        return "--exercises: '" + v +
               "' is not a folder (a course folder is laid out as exercises/: LAB/NAME/rubric.json)";
      o.exerciseDirs.push_back(v);
    } else if (arg == "--class")
      o.classDir = v;
    else if (arg == "--unlisted") {
      std::error_code ec;
      if (!std::filesystem::is_directory(v, ec))
        return "--unlisted: '" + v + "' is not a folder (it holds LAB/NAME.json, an exercise's unlisted mistakes)";
      o.unlisted.push_back(v);
    } else if (arg == "--mutants") {
      std::error_code ec;
      if (!std::filesystem::is_directory(v, ec))
        return "--mutants: '" + v + "' is not a folder (it holds LAB/NAME.json, the passing mutants known harmless)";
      o.mutants = v;
    } else if (arg == "--function")
      o.function = v;
    else if (arg == "--format") {
      if (v == "classroom")
        return "--format: 'classroom' is gone with GitHub Classroom (retired in August 2026); Classroom 50, which "
               "replaces it: --format classroom50";
      if (v != "gradescope" && v != "classroom50" && v != "prairielearn" && v != "moodle" && v != "canvas")
        return "--format: invalid value '" + v + "' (valid: gradescope, classroom50, prairielearn, moodle, canvas)";
      o.format = v;
    } else if (arg == "--cache")
      o.cacheDir = v;
    else if (arg == "--jobs") {
      long n = 0;
      if (!parseWholeNumber(v, 1, 256, n)) return "--jobs: '" + v + "' is not a whole number in [1, 256]";
      o.jobs = int(n);
    } else if (arg == "--shard") {
      int i = 0, n = 0;
      char slash = 0, extra = 0;
      if (std::sscanf(v.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || n > 100000 ||
          i < 1 || i > n)
        return "--shard: '" + v + "' is not i/n with 1 <= i <= n (e.g. 3/20)";
      o.shard = i;
      o.shards = n;
    } else if (arg == "--size") {
      if (auto e = parseSize("--size", v, o.size); !e.empty()) return e;
      o.sizeGiven = true;
    } else if (arg == "--watchdog") {
      char* end = nullptr;
      o.watchdog = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(o.watchdog >= 0.1 && o.watchdog <= 3600))
        return "--watchdog: '" + v + "' is not a number of seconds in [0.1, 3600]";
    } else if (arg == "--count" || arg == "--seed" || arg == "--minutes") {
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(d >= 0) || d > 1e6 || (arg != "--minutes" && d != double(long(d))))
        return arg + ": '" + v + "' is not " + (arg == "--minutes" ? "a number of minutes" : "a whole number") +
               " in [0, 1e6]";
      if (arg == "--count")
        o.count = int(d);
      else if (arg == "--seed")
        o.seed = unsigned(d);
      else
        o.minutes = d;
    } else if (arg == "--time" || arg == "--frames") {
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(d >= 0) || d > 1e6) return arg + ": '" + v + "' is not a number >= 0";
      if (arg == "--time")
        o.time = float(d);
      else if (d < 1 || d != int(d))
        return "--frames: '" + v + "' is not an integer >= 1";
      else
        o.frames = int(d);
    } else {
      return "unknown option '" + arg +
             "' (valid: --lab, --scene, --height-map, --set, --do, --vary, --preset, --size, --camera, --time, "
             "--frames, --shaders, "
             "--backend, --dialect, --out, --measure, --exercise, --exercises, --function, --format, --all, "
             "--watchdog, --class, --pixel, --config, --json, --variable, --line, "
             "--jobs, "
             "--shard, "
             "--cache, --no-cache, --prepare, --count, "
             "--seed, --minutes)";
    }
  }
  for (auto& dir : o.shaderDirs)
    if (std::error_code ec; !std::filesystem::is_directory(dir, ec))
      return "--shaders: '" + dir.string() + "' is not a folder";
  if (std::error_code ec; !o.classDir.empty() && !std::filesystem::is_directory(o.classDir, ec))
    return "--class: '" + o.classDir.string() + "' is not a folder";
  return {};
}

}  // namespace shadelab
