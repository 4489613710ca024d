// The pixel trace as text and JSON (grade/pixel_trace.h): the tables the terminal prints and the
// window shows.
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "app/grade/traced_draw.h"
#include "app/util/format.h"

namespace shadelab {

std::string vectorText(const glm::vec4& v) {
  const int n = std::clamp(int(v.w), 1, 3);
  std::string out;
  for (int c = 0; c < n; ++c) {
    if (c > 0) out += ' ';
    out += formatSignificant(v[c], 4);
  }
  return n > 1 ? '(' + out + ')' : out;
}

std::string kindText(TracePoint::Kind kind) {
  switch (kind) {
    case TracePoint::Kind::Param:
      return "argument";
    case TracePoint::Kind::Declared:
      return "declared";
    case TracePoint::Kind::Assigned:
      return "assigned";
    case TracePoint::Kind::Returned:
      return "returned";
    case TracePoint::Kind::OutParam:
      return "out";
    default:
      return "part";
  }
}

namespace {

// A point's values at the pixel: one value, or a loop's iterations folded ("25 times: 0 0 1 ...",
// as a grid where the count is a square).
std::string valuesText(const PixelSide& side, size_t k) {
  const std::vector<glm::vec4>& it = side.iterations[k];
  if (side.reached[k] == 0 || it.empty()) return "not reached";
  if (side.reached[k] == 1) return vectorText(it.front());
  std::string out = std::to_string(side.reached[k]) + " times";
  if (std::all_of(it.begin(), it.end(), [&](const glm::vec4& v) { return v == it.front(); }))
    return out + ", each " + vectorText(it.front());
  const int side2 = int(std::lround(std::sqrt(double(it.size()))));
  const bool grid = side2 > 1 && side2 * side2 == int(it.size()) && it.front().w <= 1.0f && side2 <= 8;
  if (grid) {
    out += ", as a " + std::to_string(side2) + " x " + std::to_string(side2) + " grid:";
    for (int r = 0; r < side2; ++r) {
      out += "\n      ";
      for (int col = 0; col < side2; ++col) out += " " + formatSignificant(it[size_t(r * side2 + col)].x, 4);
    }
    return out;
  }
  out += ":";
  constexpr size_t kShown = 8;
  for (size_t i = 0; i < it.size() && i < kShown; ++i) out += " " + vectorText(it[i]);
  if (it.size() > kShown) out += " ... last " + vectorText(it.back());
  return out;
}

// Whether a table shows a point: a statement's parts only where they vary at the pixel (a loop's
// offsets, its taps: once, its variable says what they made) and not a literal; no declaration
// without a value; the departure always.
bool shown(const TracePoint& p, int reached, bool departs) {
  if (departs) return true;
  if (p.kind == TracePoint::Kind::Sub) return !p.constant && reached >= 2;
  return p.initialised;
}

// A point's row: "> line 11  lit = 25 times, ...", its verdict before a folded loop's grid.
std::string valueRow(const PixelSide& side, size_t k, const std::string& verdict, bool departs) {
  const TracePoint& p = side.values.points[k];
  const bool part = p.kind == TracePoint::Kind::Sub;
  const bool named = p.kind == TracePoint::Kind::Param || p.kind == TracePoint::Kind::Returned ||
                     p.kind == TracePoint::Kind::OutParam || part;
  std::string values = valuesText(side, k);
  const size_t grid = values.find('\n');
  values.insert(grid == std::string::npos ? values.size() : grid, verdict);
  return std::string(departs ? "> " : "  ") + "line " + std::to_string(p.line) + (part ? "    " : "  ") + p.name +
         (named ? " (" + kindText(p.kind) + ")" : "") + " = " + values;
}

std::string colourText(const glm::vec4& c) {
  return formatSignificant(c.r, 3) + " " + formatSignificant(c.g, 3) + " " + formatSignificant(c.b, 3);
}

std::string joined(const std::vector<InspectionRow>& rows) {
  std::string t;
  for (auto& row : rows) t += row.text + "\n";
  return t;
}

}  // namespace

std::vector<InspectionRow> labInspectionRows(const LabInspection& in) {
  std::vector<InspectionRow> rows;
  const auto say = [&](std::string text) { rows.push_back({std::move(text), -1, false}); };
  const LabPixelRequest& r = in.request;
  say("pixel " + std::to_string(r.pixel.x) + ", " + std::to_string(r.pixel.y) + " of the " + r.lab + " lab (" +
      std::to_string(r.size.x) + "x" + std::to_string(r.size.y) + "): the frame " + colourText(in.side.colour));
  if (!in.note.empty()) {
    say(in.note);
    return rows;
  }
  if (in.side.fragments > 1)
    say(std::to_string(in.side.fragments) + " fragments ran it here; the nearest one's values");
  say(r.file + ", " + r.function + "():");
  for (size_t k = 0; k < in.side.values.points.size(); ++k)
    if (in.side.reached[k] > 0 && shown(in.side.values.points[k], in.side.reached[k], false))
      rows.push_back({valueRow(in.side, k, "", false), int(k), false});
  return rows;
}

std::string formatLabInspection(const LabInspection& in) { return joined(labInspectionRows(in)); }

std::vector<InspectionRow> inspectionRows(const PixelInspection& in) {
  std::vector<InspectionRow> rows;
  const auto say = [&](std::string text) { rows.push_back({std::move(text), -1, false}); };
  say("pixel " + std::to_string(in.pixel.x) + ", " + std::to_string(in.pixel.y) + " of " + quoted(in.configuration) +
      " (" + in.exercise + ", " + std::to_string(in.frameSize.x) + "x" + std::to_string(in.frameSize.y) +
      "): your frame " + colourText(in.student.colour) + ", the solution's " + colourText(in.solution.colour));
  if (!in.note.empty()) {
    say(in.note);
    return rows;
  }
  if (in.student.fragments > 1)
    say(std::to_string(in.student.fragments) + " fragments ran your function here; the nearest one's values");
  const TracePoint* previous = nullptr;
  for (size_t k = 0; k < in.student.values.points.size(); ++k) {
    const TracePoint& p = in.student.values.points[k];
    const bool departs = in.departure.found && p.line == in.departure.line && p.name == in.departure.name;
    if (!shown(p, in.student.reached[k], departs)) continue;
    if (!previous || previous->function != p.function) say(in.file + ", " + p.function + "():");
    previous = &p;
    // A return against the solution's at the pixel; any other value against every value the
    // solution computes around it.
    std::string verdict;
    if (p.kind == TracePoint::Kind::Returned && in.bothReturned && in.student.reached[k] > 0)
      verdict = in.returnsDiffer() ? "  the solution returns " + vectorText(in.solutionReturns) : "  as the solution's";
    else if (in.student.reached[k] > 0 && !in.agreement[k].reached)
      verdict = "  (too few pixels around to compare)";
    else if (in.student.reached[k] > 0)
      verdict = in.agreement[k].matches ? "  a value the solution computes" : "  none of the solution's values";
    rows.push_back({valueRow(in.student, k, verdict, departs), int(k), departs});
  }
  // Where no line stands out, only what the marks show.
  if (in.departure.found) {
    say(in.departure.text);
  } else if (in.firstUnmatched >= 0) {
    const TracePoint& p = in.student.values.points[size_t(in.firstUnmatched)];
    say("the trace cannot single out the line where your values part from the solution's; the first line whose "
        "values around this pixel are none of the solution's is line " +
        std::to_string(p.line) + " (`" + p.name + "`)");
  } else if (in.returnsDiffer()) {
    say("every value of yours around this pixel is one the solution computes, in some other place: the trace "
        "cannot single out a line");
  } else if (!in.bothReturned) {
    say("every value traced around this pixel is one the solution computes; what your function returns is not "
        "traced (a matrix or a structure), so this does not say that it is the solution's");
  } else {
    say("your values around this pixel are the solution's, and so is what you return here: look where the "
        "frames differ");
  }
  return rows;
}

std::string formatInspection(const PixelInspection& in) { return joined(inspectionRows(in)); }

nlohmann::json toJson(const PixelInspection& in) {
  const auto vec = [](const glm::vec4& v) {
    nlohmann::json a = nlohmann::json::array();
    for (int c = 0; c < std::clamp(int(v.w), 1, 3); ++c)
      a.push_back(std::isfinite(v[c]) ? nlohmann::json(v[c]) : nullptr);
    return a;
  };
  nlohmann::json lines = nlohmann::json::array();
  for (size_t k = 0; k < in.student.values.points.size(); ++k) {
    const TracePoint& p = in.student.values.points[k];
    nlohmann::json values = nlohmann::json::array();
    for (auto& v : in.student.iterations[k]) values.push_back(vec(v));
    lines.push_back({{"line", p.line},
                     {"function", p.function},
                     {"name", p.name},
                     {"kind", kindText(p.kind)},
                     {"reached", in.student.reached[k]},
                     {"values", values},
                     {"compared", in.agreement[k].reached},
                     {"solution_computes", in.agreement[k].matches}});
  }
  const nlohmann::json solutionResult = in.bothReturned ? vec(in.solutionReturns) : nlohmann::json();
  return {{"exercise", in.exercise},
          {"configuration", in.configuration},
          {"file", in.file},
          {"pixel", {in.pixel.x, in.pixel.y}},
          {"colour",
           {{"yours", vec({glm::vec3(in.student.colour), 3.0f})},
            {"solution", vec({glm::vec3(in.solution.colour), 3.0f})}}},
          {"fragments", in.student.fragments},
          {"lines", lines},
          {"solution_returns", solutionResult},
          {"departure", toJson(in.departure)},
          {"first_unmatched_line",
           in.firstUnmatched >= 0 ? nlohmann::json(in.student.values.points[size_t(in.firstUnmatched)].line) : nullptr},
          {"note", in.note}};
}

}  // namespace shadelab
