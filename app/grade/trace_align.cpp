// The trace's second half (grade/trace.h): the student's values aligned with the solution's, the
// line where they part, its sentence, and the finding as it travels in a report.
#include "app/grade/trace.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "app/util/format.h"

namespace shadelab {

namespace {

constexpr int kFewestRows = 8;          // rows both sides must reach before their values say anything
constexpr double kMatchingRows = 0.98;  // the share of those rows that must agree (a kink's neighbours may not)

// Two values one computation apart in rounding: relative, with a floor small beside the values a
// draw's derivatives take (a texel's worth of position across one pixel is around 1e-3, products
// of two such around 1e-5, so a floor there would make them all one value).
bool close(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-7 + 3e-4 * std::max(std::abs(a), std::abs(b));
}

int componentsAt(const std::vector<glm::vec4>& v) {
  int n = 0;
  for (auto& x : v) n = std::max(n, std::min(3, int(x.w)));
  return n;
}

// Whether component `ca` of `a` is, row by row, f(component `cb` of `b`), on the rows `a` reached:
// `b` must have been reached on them too (a value of one branch of the solution's, reached on a
// third of the rows, says nothing of the other two).
template <typename F>
bool follows(const std::vector<glm::vec4>& a, int ca, const std::vector<glm::vec4>& b, int cb, F f) {
  size_t mine = 0, both = 0, agree = 0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r) {
    if (a[r].w <= 0.0f) continue;
    ++mine;
    if (b[r].w <= 0.0f) continue;
    ++both;
    agree += close(a[r][ca], f(b[r][cb]));
  }
  return both >= size_t(kFewestRows) && double(both) >= kMatchingRows * double(mine) &&
         double(agree) >= kMatchingRows * double(both);
}

bool reached(const std::vector<glm::vec4>& v) {
  return std::count_if(v.begin(), v.end(), [](const glm::vec4& x) { return x.w > 0.0f; }) >= kFewestRows;
}

// The value of component c on every row it was reached, if it is one constant.
bool constantValue(const std::vector<glm::vec4>& v, int c, float& value) {
  bool first = true;
  for (auto& x : v) {
    if (x.w <= 0.0f) continue;
    if (first) {
      value = x[c];
      first = false;
    } else if (!close(x[c], value)) {
      return false;
    }
  }
  return !first;
}

// What a point is called when its role is looked for on the other side: a variable by its name,
// an expression by its text, a result as the result.
std::string roleOf(const TracePoint& p) {
  switch (p.kind) {
    case TracePoint::Kind::Returned:
      return "return " + p.function;
    case TracePoint::Kind::OutParam:
      return "out " + p.function + " " + p.name;
    case TracePoint::Kind::Param:
      return "in " + p.function + " " + p.name;
    default:
      return p.function + " " + p.name;
  }
}

class Aligner {
 public:
  Aligner(const TraceValues& student, const TraceValues& solution) : st_(student), so_(solution) {
    for (size_t q = 0; q < so_.points.size(); ++q) roles_[roleOf(so_.points[q])].push_back(&so_.values[q]);
    // A function with several returns returns, on each row, what the one reached there returns.
    for (auto& [role, values] : roles_) {
      if (values.size() < 2 || !role.starts_with("return ")) continue;
      std::vector<glm::vec4> merged(values.front()->size(), glm::vec4(0.0f));
      for (auto* v : values)
        for (size_t r = 0; r < merged.size() && r < v->size(); ++r)
          if ((*v)[r].w > 0.0f) merged[r] = (*v)[r];
      values.push_back(&merged_.emplace_back(std::move(merged)));
    }
  }

  // Whether the student's point k holds its role's values: where the solution has a point in the
  // same role (its result, a variable of the same name, an expression written the same way) that
  // is reached where k is, k must hold that point's values, component for component; a value that
  // is some other of the solution's values there has left the solution's path (an index one texel
  // on is the solution's next index, not its index). Elsewhere, any value the solution computes.
  bool holdsRole(int k) {
    if (auto it = roleMemo_.find(k); it != roleMemo_.end()) return it->second;
    const int role = namesakeState(k);
    return roleMemo_[k] = role == kNoNamesake ? matches(k) : role == kNamesakeHeld;
  }
  // Whether k has a namesake whose values it does not hold, though they are values the solution
  // computes: the sentence says it does not hold its namesake's values, not "none of its steps".
  bool leftItsRole(int k) { return namesakeState(k) == kNamesakeLeft && matches(k); }

  // Whether the student's point k is a value the solution computes: a scalar, any of its values'
  // components; a vector, one of its vectors whole, component for component (x and y exchanged
  // is another value; a 0.0 or 1.0 written into it stands for itself).
  bool matches(int k) {
    if (auto it = memo_.find(k); it != memo_.end()) return it->second;
    const auto& a = st_.values[k];
    const int n = componentsAt(a);
    // What no input reaches (a literal, a texture's size, a product of uniforms) can be told
    // wrong only against a value of the solution's that no input reaches either; where the
    // solution has none of its size, it is given, like a uniform. A value the inputs reach that
    // comes out constant (a channel the map does not hold) must be the solution's like any other.
    if (!readsInputs(k) && !solutionHasInputFree(n)) return memo_[k] = true;
    bool found = n == 1 && componentMatches(a, 0, !readsInputs(k));
    for (size_t q = 0; n > 1 && q < so_.values.size() && !found; ++q) {
      const auto& b = so_.values[q];
      if (componentsAt(b) != n) continue;
      bool all = true;
      for (int c = 0; c < n && all; ++c) all = constantMatches(a, c) || follows(a, c, b, c, [](float x) { return x; });
      found = all;
    }
    return memo_[k] = found;
  }
  // Whether the solution computes a value of n components that no input reaches.
  bool solutionHasInputFree(int n) const {
    for (size_t q = 0; q < so_.points.size(); ++q)
      if (so_.points[q].kind != TracePoint::Kind::Param && componentsAt(so_.values[q]) == n &&
          !readsInputs(so_, q, solutionReads_))
        return true;
    return false;
  }
  bool readsInputs(int k) { return readsInputs(st_, size_t(k), reads_); }
  static bool readsInputs(const TraceValues& side, size_t k, std::map<size_t, bool>& memo) {
    if (auto it = memo.find(k); it != memo.end()) return it->second;
    memo[k] = false;  // a loop's value reads itself
    const TracePoint& p = side.points[k];
    bool reads = p.kind == TracePoint::Kind::Param;
    for (int q : p.from) reads = reads || readsInputs(side, size_t(q), memo);
    return memo[k] = reads;
  }
  // Whether each component of point k is somewhere among the solution's values (in any place):
  // a value made of the solution's, rearranged, rather than one it never computes.
  bool componentsFound(int k) {
    const auto& a = st_.values[k];
    const int n = componentsAt(a);
    bool all = n > 0;
    for (int c = 0; c < n && all; ++c) all = componentMatches(a, c, true);
    return all;
  }
  bool reachedPoint(int k) const { return reached(st_.values[k]); }

 private:
  static constexpr int kNoNamesake = 0, kNamesakeHeld = 1, kNamesakeLeft = 2;
  int namesakeState(int k) {
    const TracePoint& p = st_.points[size_t(k)];
    const auto it = roles_.find(roleOf(p));
    // A value no input reaches is told wrong against the solution's own such values (matches).
    if (it == roles_.end() || !readsInputs(k)) return kNoNamesake;
    const auto& a = st_.values[size_t(k)];
    const int n = componentsAt(a);
    bool any = false;
    for (const auto* v : it->second) {
      const auto& b = *v;
      if (componentsAt(b) != n || !coReached(a, b)) continue;
      any = true;
      bool all = n > 0;
      for (int c = 0; c < n && all; ++c) all = follows(a, c, b, c, [](float x) { return x; });
      if (all) return kNamesakeHeld;
    }
    return any ? kNamesakeLeft : kNoNamesake;
  }
  // Whether `b` was reached on (almost) every row `a` was: only then do its values stand for a's role.
  static bool coReached(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    size_t mine = 0, both = 0;
    for (size_t r = 0; r < a.size() && r < b.size(); ++r) {
      if (a[r].w <= 0.0f) continue;
      ++mine;
      both += b[r].w > 0.0f;
    }
    return both >= size_t(kFewestRows) && double(both) >= kMatchingRows * double(mine);
  }

  // A component constant over every row reached, at 0, 1 or a number the solution writes.
  bool constantMatches(const std::vector<glm::vec4>& a, int c) const {
    float value = 0.0f;
    if (!constantValue(a, c, value)) return false;
    if (close(value, 0.0f) || close(value, 1.0f)) return true;
    for (double l : so_.literals)
      if (close(value, float(l))) return true;
    return false;
  }
  bool componentMatches(const std::vector<glm::vec4>& a, int c, bool constantsCount) {
    if (constantsCount && constantMatches(a, c)) return true;
    // A constant is told apart only by a value of the solution's that is one number too: a
    // vector's constant component (the green of a one-channel map) says nothing.
    float value = 0.0f;
    const bool constant = constantValue(a, c, value);
    for (size_t q = 0; q < so_.values.size(); ++q) {
      const auto& b = so_.values[q];
      const int m = componentsAt(b);
      if (constant && m != 1) continue;
      for (int cb = 0; cb < m; ++cb)
        if (follows(a, c, b, cb, [](float x) { return x; })) return true;
    }
    for (auto& q : so_.quantities) {
      if (constant) break;
      std::vector<glm::vec4> b(q.size());
      for (size_t r = 0; r < q.size(); ++r) b[r] = {q[r], 0.0f, 0.0f, 1.0f};
      if (follows(a, c, b, 0, [](float x) { return x; }) || follows(a, c, b, 0, [](float x) { return 1.0f / x; }) ||
          follows(a, c, b, 0, [](float x) { return x * x; }) ||
          follows(a, c, b, 0, [](float x) { return 1.0f / (x * x); }) ||
          follows(a, c, b, 0, [](float x) { return x >= 0.0f ? std::sqrt(x) : std::nanf(""); }))
        return true;
    }
    return false;
  }

  const TraceValues& st_;
  const TraceValues& so_;
  std::map<int, bool> memo_, roleMemo_;
  std::map<std::string, std::vector<const std::vector<glm::vec4>*>> roles_;
  std::deque<std::vector<glm::vec4>> merged_;  // results merged over returns (stable addresses)
  std::map<size_t, bool> reads_;
  mutable std::map<size_t, bool> solutionReads_;
};

// How `a` relates to `b` (same component count), in words: "" when no simple relation fits.
std::string relationTo(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, const std::string& what) {
  const int n = componentsAt(a);
  if (n == 0 || componentsAt(b) != n) return "";
  const auto all = [&](auto f) {
    for (int c = 0; c < n; ++c)
      if (!follows(a, c, b, c, f)) return false;
    return true;
  };
  if (all([](float x) { return -x; })) return what + ", negated";
  if (all([](float x) { return 1.0f - x; })) return "one minus " + what;
  if (all([](float x) { return x * x; })) return what + ", squared";
  if (all([](float x) { return x >= 0.0f ? std::sqrt(x) : std::nanf(""); })) return "the square root of " + what;
  if (all([](float x) { return 1.0f / x; })) return "one over " + what;
  // A constant factor: fitted on the rows where b is far from zero, then checked on every row.
  double num = 0.0, den = 0.0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r)
    for (int c = 0; c < n; ++c)
      if (a[r].w > 0.0f && b[r].w > 0.0f && std::isfinite(a[r][c]) && std::isfinite(b[r][c])) {
        num += double(a[r][c]) * b[r][c];
        den += double(b[r][c]) * b[r][c];
      }
  if (den > 1e-12) {
    const float k = float(num / den);
    if (std::abs(k - 1.0f) > 1e-3f && std::abs(k) > 1e-4f && all([k](float x) { return k * x; }))
      return formatNumber(std::round(k * 1000.0) / 1000.0) + " times " + what;
  }
  // A constant offset.
  double sum = 0.0;
  size_t count = 0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r)
    if (a[r].w > 0.0f && b[r].w > 0.0f && std::isfinite(a[r][0]) && std::isfinite(b[r][0])) {
      sum += double(a[r][0]) - b[r][0];
      ++count;
    }
  if (count > 0) {
    const float d = float(sum / double(count));
    if (std::abs(d) > 1e-4f && all([d](float x) { return x + d; }))
      return what + (d > 0 ? " plus " : " minus ") + formatNumber(std::round(std::abs(d) * 10000.0) / 10000.0);
  }
  return "";
}

// Whether `a` holds the components of `b` in another order: "x and y exchanged", or "".
std::string rearranged(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  const int n = componentsAt(a);
  if (n < 2 || componentsAt(b) != n) return "";
  int from[3] = {-1, -1, -1};
  bool moved = false;
  for (int c = 0; c < n; ++c) {
    for (int d = 0; d < n && from[c] < 0; ++d)
      if (follows(a, c, b, d, [](float x) { return x; })) from[c] = d;
    if (from[c] < 0) return "";
    moved |= from[c] != c;
  }
  if (!moved) return "";
  std::string moves;
  for (int c = 0; c < n; ++c)
    if (from[c] != c && from[c] > c && from[from[c]] == c)
      moves += std::string(moves.empty() ? "" : ", ") + "xyz"[c] + " and " + "xyz"[from[c]] + " exchanged";
  if (moves.empty())
    for (int c = 0; c < n; ++c)
      if (from[c] != c) moves += std::string(moves.empty() ? "" : ", ") + "xyz"[c] + " holding " + "xyz"[from[c]];
  return moves;
}

}  // namespace

TraceFinding alignTraces(const TraceValues& student, const TraceValues& solution,
                         const std::vector<std::pair<std::string, std::string>>& inputs, const std::string& file) {
  TraceFinding out;
  Aligner align(student, solution);
  const auto wrong = [&](int k) { return align.reachedPoint(k) && !align.holdsRole(k); };
  // Where to start: the student's results that differ from the solution's result.
  int solutionResult = -1;
  for (size_t k = 0; k < solution.points.size(); ++k)
    if (solution.points[k].kind == TracePoint::Kind::Returned && reached(solution.values[k])) solutionResult = int(k);
  // The student's results: what it returns and its out-parameters; where the result has no tap of
  // its own (a matrix), the parts it is built of.
  std::vector<int> results;
  for (size_t k = 0; k < student.points.size(); ++k) {
    const TracePoint& p = student.points[k];
    if (p.kind == TracePoint::Kind::Returned || p.kind == TracePoint::Kind::OutParam)
      results.push_back(int(k));
    else if (p.partOfResult)
      for (int part : align.reachedPoint(int(k)) ? std::vector<int>{int(k)} : p.from) results.push_back(part);
  }
  int departure = -1;
  for (int k : results) {
    if (!wrong(k)) continue;
    // Down through what it is made of, always into the earliest value that is wrong.
    int at = int(k);
    std::set<int> seen;
    for (;;) {
      seen.insert(at);
      // A value the solution never computes before one that only rearranges the solution's values.
      int next = -1;
      bool nextNovel = false;
      for (int q : student.points[at].from) {
        if (seen.count(q) || !wrong(q)) continue;
        const bool novel = !align.componentsFound(q);
        if (next < 0 || (novel && !nextNovel) ||
            (novel == nextNovel && student.points[q].line < student.points[next].line)) {
          next = q;
          nextNovel = novel;
        }
      }
      if (next < 0) break;
      at = next;
    }
    if (departure < 0 || student.points[at].line < student.points[departure].line) departure = at;
  }
  if (departure < 0) return out;
  const TracePoint& p = student.points[departure];
  out.found = true;
  out.line = p.line;
  out.function = p.function;
  // A statement's whole value is named by its variable.
  out.name =
      (p.kind == TracePoint::Kind::Sub && !p.statement.empty() && p.statement != "return") ? p.statement : p.name;
  for (int q : p.from) {
    const TracePoint& o = student.points[q];
    if (align.reachedPoint(q) && !o.constant && align.holdsRole(q)) out.matching.push_back(o.name);
  }
  std::sort(out.matching.begin(), out.matching.end());
  out.matching.erase(std::unique(out.matching.begin(), out.matching.end()), out.matching.end());
  // "Up to here" only where it is so: every value the student computes on earlier lines matches.
  bool earlierMatch = true;
  for (size_t k = 0; k < student.points.size(); ++k) {
    const TracePoint& o = student.points[k];
    if (o.function != p.function || o.line >= p.line || !align.reachedPoint(int(k)) || o.constant) continue;
    if (align.holdsRole(int(k)))
      ++out.matchedBefore;
    else
      earlierMatch = false;
  }
  if (solutionResult >= 0)
    out.relation = relationTo(student.values[departure], solution.values[solutionResult], "the solution's result");
  // How it relates to an input it is not written from (of one it is, the code itself says as much).
  std::set<std::string> readsDirectly;
  for (int q : p.from) readsDirectly.insert(student.points[q].name);
  if (out.relation.empty())
    for (auto& [name, says] : inputs)
      for (size_t q = 0; q < solution.points.size() && out.relation.empty() && !readsDirectly.count(name); ++q)
        if (solution.points[q].kind == TracePoint::Kind::Param && solution.points[q].name == name)
          out.relation = relationTo(student.values[departure], solution.values[q], says);
  // A value of the solution's with its components in another order.
  for (size_t q = 0; q < solution.points.size() && out.relation.empty(); ++q)
    if (const std::string moves = rearranged(student.values[departure], solution.values[q]); !moves.empty())
      out.relation = "one of the solution's values with its components in another order (" + moves + ")";
  // The sentence: the line, what matches up to it, and what its value is; never the solution's code.
  std::string t = "Line " + std::to_string(p.line) + " of " + file + " (`" + out.name + "`): ";
  out.upToHere = earlierMatch && out.matchedBefore > 0;
  if (out.upToHere) t += "your values up to this line match the solution's; here ";
  const std::string what =
      p.kind == TracePoint::Kind::Returned ? "what " + p.function + "() returns" : "`" + out.name + "`";
  if (!align.leftItsRole(departure))
    t += what + " takes values that none of the solution's steps take";
  else if (p.kind == TracePoint::Kind::Returned)
    t += what + " is not what the solution returns (the solution computes these values on its way)";
  else
    t += what + " does not hold the values of the solution's " +
         (p.kind == TracePoint::Kind::Sub ? "expression written the same way" : "`" + p.name + "`") +
         " (the solution computes them elsewhere)";
  if (!out.matching.empty())
    t += ", though " + englishList(out.matching, "`") + ", which it is made of, " +
         (out.matching.size() == 1 ? "matches" : "match") + " the solution's values";
  t += ".";
  if (!out.relation.empty()) t += " It is " + out.relation + ".";
  out.text = t;
  return out;
}

std::vector<PointAgreement> pointAgreement(const TraceValues& student, const TraceValues& solution) {
  Aligner align(student, solution);
  std::vector<PointAgreement> out(student.points.size());
  for (size_t k = 0; k < out.size(); ++k) {
    out[k].reached = align.reachedPoint(int(k));
    out[k].matches = out[k].reached && align.holdsRole(int(k));
  }
  return out;
}

std::string TraceFinding::evidence(const std::string& configuration) const {
  const std::string side = std::to_string(kTraceBlockSide);
  return inDraw() ? "every value your function computes in the lab's own draw, traced beside the solution's at the " +
                        side + " x " + side + " pixels around pixel " + std::to_string(pixel.x) + ", " +
                        std::to_string(pixel.y) + " of " + quoted(configuration) + ", where your frame differs most"
                  : "every value your function computes, traced beside the solution's on the same table of inputs, " +
                        quoted(configuration);
}

nlohmann::json toJson(const TraceFinding& f) {
  return {{"found", f.found},
          {"line", f.line},
          {"name", f.name},
          {"function", f.function},
          {"matching", f.matching},
          {"relation", f.relation},
          {"matched_before", f.matchedBefore},
          {"up_to_here", f.upToHere},
          {"text", f.text},
          {"pixel", {f.pixel.x, f.pixel.y}}};
}

TraceFinding traceFindingFromJson(const nlohmann::json& j) {
  TraceFinding f;
  if (!j.is_object()) return f;
  f.found = j.value("found", false);
  f.line = j.value("line", 0);
  f.name = j.value("name", std::string());
  f.function = j.value("function", std::string());
  if (j.contains("matching") && j["matching"].is_array())
    for (auto& m : j["matching"])
      if (m.is_string()) f.matching.push_back(m.get<std::string>());
  f.relation = j.value("relation", std::string());
  f.matchedBefore = j.value("matched_before", 0);
  f.upToHere = j.value("up_to_here", false);
  f.text = j.value("text", std::string());
  if (j.contains("pixel") && j["pixel"].is_array() && j["pixel"].size() == 2 && j["pixel"][0].is_number_integer() &&
      j["pixel"][1].is_number_integer())
    f.pixel = {j["pixel"][0].get<int>(), j["pixel"][1].get<int>()};
  return f;
}

}  // namespace shadelab
