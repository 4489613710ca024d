#include "app/grade/probe_trace.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "app/shader/function_parts.h"
#include "app/shader/preprocessor.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

int lineOf(const std::string& text, size_t at) {
  return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(std::min(at, text.size())), '\n'));
}

// The lines of `file` that a build's errors name.
std::vector<int> errorLines(const std::vector<std::string>& errors, const std::string& file) {
  std::vector<int> lines;
  const std::regex at(std::regex_replace(file, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + R"(:(\d+):)");
  for (auto& e : errors)
    for (auto it = std::sregex_iterator(e.begin(), e.end(), at); it != std::sregex_iterator(); ++it)
      lines.push_back(std::stoi((*it)[1]));
  return lines;
}

}  // namespace

std::vector<std::string> tracedFunctions(const Exercise& ex) {
  const std::string& file = ex.files.front();
  const std::string starter = readWholeFile(ex.dir / "starter" / file);
  const std::vector<FunctionSpan> spans = findFunctions(starter);
  std::vector<std::string> names;
  TodoRegion r;
  const bool region = findTodoRegion(starter, ex.id, r);
  const int from = region ? lineOf(starter, r.from) : 0, to = region ? lineOf(starter, r.to) : 0;
  for (auto& s : spans)
    if (!region || (s.firstLine <= to && s.lastLine >= from)) names.push_back(s.name);
  return names;
}

std::string instrumentAndDraw(const std::string& file, const std::vector<std::string>& functions,
                              const std::string& source, const TraceDraw& draw, InstrumentedSource& built,
                              bool derivativesAllowed) {
  if (functions.empty()) return "no function of " + file + " holds the exercise's TODO region";
  std::vector<int> quiet;
  std::string lastError;
  // Each round drops the taps the compiler refused, by line; the last keeps the variables alone.
  constexpr int kRounds = 4;
  for (int round = 0; round < kRounds; ++round) {
    const bool sub = round + 1 < kRounds;
    InstrumentedSource inst = instrumentFunctions(source, functions, quiet, sub, derivativesAllowed);
    if (!inst.error.empty()) return inst.error;
    std::vector<std::string> errors;
    if (auto e = draw(inst, errors); !e.empty()) return e;
    if (errors.empty()) {
      built = std::move(inst);
      return {};
    }
    lastError = errors.front().substr(0, errors.front().find('\n'));
    const std::vector<int> lines = errorLines(errors, file);
    if (lines.empty()) round = std::max(round, kRounds - 2);  // nothing to drop by line: the variables alone
    quiet.insert(quiet.end(), lines.begin(), lines.end());
  }
  return "the instrumented function does not build (" + lastError + ")";
}

std::string traceSide(const Exercise& ex, const FunctionProbe& probe, int block,
                      const std::vector<std::string>& functions, const std::string& source,
                      const std::vector<fs::path>& roots, TraceValues& out) {
  const std::string& file = ex.files.front();
  ImageF image;
  InstrumentedSource inst;
  const auto draw = [&](const InstrumentedSource& i, std::vector<std::string>& errors) {
    return drawFunctionTrace(probe, roots, {file, i.text, int(i.points.size()), block}, image, errors);
  };
  if (auto e = instrumentAndDraw(file, functions, source, draw, inst); !e.empty()) return e;
  out.points = inst.points;
  out.literals = inst.literals;
  out.values.assign(inst.points.size(), {});
  for (size_t k = 0; k < inst.points.size(); ++k)
    for (int row = 0; row < image.size.x; ++row) {
      const float* px = image.at(row, int(k));
      out.values[k].push_back({px[0], px[1], px[2], px[3]});
    }
  return {};
}

std::string traceOnProbe(const Exercise& ex, const FunctionProbe& probe, const std::vector<fs::path>& studentRoots,
                         const ImageF& table, const ImageF& solution, TraceFinding& out) {
  // The first block of uniforms whose base draw differs (the strength at 1 may hide what the
  // strength at 2.5 shows).
  int block = -1;
  for (int b = 0; b < int(probe.blocks.size()) && b < table.size.y && b < solution.size.y; ++b) {
    double most = 0.0;
    for (int row = 0; row < table.size.x && row < solution.size.x; ++row)
      for (int c = 0; c < 3; ++c) {
        const float x = table.at(row, b)[c], y = solution.at(row, b)[c];
        most = std::max(most, std::isfinite(x) && std::isfinite(y) ? double(std::abs(x - y)) : 1.0);
      }
    if (most > 1e-3) {
      block = b;
      break;
    }
  }
  if (block < 0) return {};  // the same values on every block: nothing parts
  const std::string& file = ex.files.front();
  if (file.ends_with(kPartSuffix)) return "a part file is not traced yet";
  const ShaderSearchPath submitted(studentRoots);
  const ShaderSearchPath::Lookup found = submitted.find(file);
  if (found.file.empty()) return file + " is not in the student's folders";
  const std::string student = readWholeFile(found.file);
  const std::vector<std::string> functions = tracedFunctions(ex);  // the starter read once, for both sides
  TraceValues mine, theirs;
  if (auto e = traceSide(ex, probe, block, functions, student, studentRoots, mine); !e.empty())
    return "your " + file + ": " + e;
  if (auto e = traceSide(ex, probe, block, functions, labText(ex, file), {builtinShaderDir()}, theirs); !e.empty())
    return "the solution's " + file + ": " + e;
  const std::vector<FunctionProbe::Draw> draws = probe.draws();
  for (size_t d = 0; d < draws.size() && int(d) < table.size.y; ++d)
    if (draws[d].kind == FunctionProbe::Draw::Kind::Quantity) {
      std::vector<float> q;
      for (int row = 0; row < table.size.x; ++row) q.push_back(table.at(row, int(d))[0]);
      theirs.quantities.push_back(std::move(q));
    }
  std::vector<std::pair<std::string, std::string>> inputs;
  for (auto& in : probe.inputs) inputs.push_back({in.name, in.says});
  out = alignTraces(mine, theirs, inputs, file);
  return {};
}

}  // namespace shadelab
