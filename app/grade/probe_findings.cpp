// What a student's probe table says against the solution's (grade/function_probe.h: analyseProbe).
// Every finding is measured on the tables alone: which rows differ, which draws move, what
// transform of the solution's values lands on the student's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/glm.hpp>

#include "app/grade/function_probe.h"
#include "app/util/format.h"

namespace shadelab {

namespace {

// A finding must fit this well: its residual at most this share of the student's distance from the
// solution (a frame's relations allow kFrameFit over noisier pictures; a table is exact).
constexpr double kTableFit = 0.1;

std::string number(double v) { return formatSignificant(v, 3); }

std::string count(size_t n, size_t of) { return std::to_string(n) + " of " + std::to_string(of); }

// The tables and the questions asked of them.
struct Tables {
  const FunctionProbe& probe;
  const ImageF &student, &solution;
  std::vector<FunctionProbe::Draw> draws = probe.draws();

  glm::vec3 at(const ImageF& image, int draw, int row) const {
    const float* p = image.at(row, draw);
    glm::vec3 v(0.0f);
    for (int c = 0; c < probe.size; ++c) v[c] = p[c];
    return v;
  }
  static bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
  // Two results differ beyond rounding: 1e-3 of their size, and at least 1e-3.
  static bool apart(const glm::vec3& a, const glm::vec3& b) {
    if (finite(a) != finite(b)) return true;
    if (!finite(a)) return false;
    const float d = glm::length(a - b), s = std::max(glm::length(a), glm::length(b));
    return d > 1e-3f * (1.0f + s);
  }
  int drawOf(FunctionProbe::Draw::Kind kind, int block, int index) const {
    for (size_t d = 0; d < draws.size(); ++d)
      if (draws[d].kind == kind && draws[d].block == block && draws[d].index == index) return int(d);
    return -1;
  }
  int base(int block) const { return drawOf(FunctionProbe::Draw::Kind::Base, block, -1); }
  int rows() const { return probe.totalRows(); }
  // Which edge a row belongs to (-1: the lab's rows).
  int edgeOf(int row) const { return row < probe.rows ? -1 : (row - probe.rows) / FunctionProbe::kEdgeRows; }

  // RMS of student - transform(solution) over the base draws' finite rows (every block).
  double residual(const std::function<glm::vec3(const glm::vec3&, int draw, int row)>& transform) const {
    double sum = 0.0;
    size_t n = 0;
    for (size_t b = 0; b < probe.blocks.size(); ++b)
      for (int r = 0; r < rows(); ++r) {
        const glm::vec3 s = at(student, base(int(b)), r), p = at(solution, base(int(b)), r);
        if (!finite(s) || !finite(p)) continue;
        const glm::vec3 d = s - transform(p, base(int(b)), r);
        sum += glm::dot(d, d);
        ++n;
      }
    return n ? std::sqrt(sum / double(n)) : 0.0;
  }
  // How often each side moves between two draws, over the lab's rows: {solution, student, both}.
  struct Moves {
    size_t solution = 0, student = 0, both = 0, rows = 0;
  };
  Moves moves(int drawA, int drawB) const {
    Moves m;
    for (int r = 0; r < probe.rows; ++r) {
      const bool p = apart(at(solution, drawA, r), at(solution, drawB, r));
      const bool s = apart(at(student, drawA, r), at(student, drawB, r));
      m.solution += p;
      m.student += s;
      m.both += p && s;
      ++m.rows;
    }
    return m;
  }
};

std::string theResult(const FunctionProbe& probe) { return "your function's " + probe.says; }

}  // namespace

std::vector<ProbeFinding> analyseProbe(const FunctionProbe& probe, const ImageF& student, const ImageF& solution,
                                       const ImageF* starter) {
  std::vector<ProbeFinding> out;
  const Tables t{probe, student, solution};
  if (student.size != solution.size || student.size.y != int(t.draws.size()) || student.size.x != t.rows()) return out;
  const std::string result = theResult(probe);
  const double distance = t.residual([](const glm::vec3& p, int, int) { return p; });

  // Non-finite results where the solution's are finite: where they are, by edge and block.
  {
    size_t bad = 0, total = 0;
    std::vector<size_t> byEdge(probe.edges.size() + 1, 0);
    for (size_t b = 0; b < probe.blocks.size(); ++b)
      for (int r = 0; r < t.rows(); ++r, ++total) {
        const glm::vec3 s = t.at(student, t.base(int(b)), r), p = t.at(solution, t.base(int(b)), r);
        if (!Tables::finite(s) && Tables::finite(p)) {
          ++bad;
          ++byEdge[size_t(t.edgeOf(r) + 1)];
        }
      }
    if (bad > 0) {
      std::string where;
      for (size_t e = 0; e < probe.edges.size(); ++e)
        if (byEdge[e + 1] == bad) where = ", all of them " + probe.edges[e].says;
      out.push_back({"non-finite", "",
                     "Your function returns NaN or Inf for " + count(bad, total) + " inputs probed" + where +
                         ", where the solution's result is finite: a division by a length or a value that reaches "
                         "0 there, or the square root of a negative number.",
                     0.0});
      for (size_t e = 0; e < probe.edges.size(); ++e)
        if (byEdge[e + 1] == bad) out.back().key = probe.edges[e].name;
    }
  }
  if (distance <= 1e-4) {
    out.push_back({"agrees", "", "Your function returns what the solution's returns on every input probed.", 0.0});
    return out;
  }

  // The starter's table: nothing written reaches the result.
  if (starter && starter->size == student.size) {
    const Tables s{probe, student, *starter};
    const double toStarter = s.residual([](const glm::vec3& p, int, int) { return p; });
    if (toStarter <= 1e-4 * (1.0 + distance))
      out.push_back({"starter", "",
                     "Your function returns what the starter's placeholder returns on every input probed: what you "
                     "wrote does not reach its result.",
                     0.0});
  }

  // The solution's result for inputs turned round.
  for (size_t k = 0; k < probe.transforms.size(); ++k) {
    const int draw = t.drawOf(FunctionProbe::Draw::Kind::Transform, 0, int(k));
    double sum = 0.0, base = 0.0;
    size_t n = 0;
    for (int r = 0; r < t.rows(); ++r) {
      const glm::vec3 s = t.at(student, t.base(0), r), p = t.at(solution, draw, r), q = t.at(solution, t.base(0), r);
      if (!Tables::finite(s) || !Tables::finite(p) || !Tables::finite(q)) continue;
      sum += glm::dot(s - p, s - p);
      base += glm::dot(s - q, s - q);
      ++n;
    }
    if (n == 0 || base <= 1e-8 * double(n)) continue;
    const double fit = std::sqrt(sum / base);
    if (fit <= kTableFit)
      out.push_back({"transform", probe.transforms[k].name,
                     "On every input probed, " + result + " is the solution's with " + probe.transforms[k].says +
                         ": your function reads that input turned round.",
                     fit});
  }

  // A relation of the two results.
  if (distance > 0.0) {
    struct Candidate {
      std::string kind, text;
      std::function<glm::vec3(const glm::vec3&, int, int)> transform;
    };
    double dot = 0.0, norm = 0.0, offset = 0.0;
    size_t n = 0;
    for (size_t b = 0; b < probe.blocks.size(); ++b)
      for (int r = 0; r < t.rows(); ++r) {
        const glm::vec3 s = t.at(student, t.base(int(b)), r), p = t.at(solution, t.base(int(b)), r);
        if (!Tables::finite(s) || !Tables::finite(p)) continue;
        dot += glm::dot(s, p);
        norm += glm::dot(p, p);
        offset += double(glm::dot(s - p, glm::vec3(1.0f))) / probe.size;
        ++n;
      }
    const float a = norm > 0.0 ? float(dot / norm) : 1.0f, b = n ? float(offset / double(n)) : 0.0f;
    const glm::vec3 mask(1.0f, probe.size > 1 ? 1.0f : 0.0f, probe.size > 2 ? 1.0f : 0.0f);
    std::vector<Candidate> candidates{
        {"zero", "is 0 on every input probed: nothing of the inputs reaches it",
         [](const glm::vec3&, int, int) { return glm::vec3(0.0f); }},
        {"negated", "is the solution's with its sign turned over: a direction or a difference taken the other way",
         [](const glm::vec3& p, int, int) { return -p; }},
        {"complement", "is 1 minus the solution's: the result turned over",
         [&](const glm::vec3& p, int, int) { return mask - p; }},
        {"scaled", "is the solution's scaled by " + number(a) + ": a factor missing, extra or applied twice",
         [a](const glm::vec3& p, int, int) { return a * p; }},
        {"offset",
         "is the solution's " + std::string(b < 0 ? "minus " : "plus ") + number(std::abs(b)) +
             ": a term added or left out",
         [&](const glm::vec3& p, int, int) { return p + b * mask; }},
        {"squared", "is the solution's squared: a factor applied twice",
         [](const glm::vec3& p, int, int) { return p * p; }},
        {"square-root", "is the square root of the solution's: a factor applied once too few",
         [](const glm::vec3& p, int, int) { return glm::sqrt(glm::max(p, 0.0f)); }},
    };
    const std::string names[] = {"x", "y", "z"};
    std::vector<std::string> comp;
    {
      std::string c = probe.components;
      for (size_t at = 0; comp.size() < 3;) {
        const size_t next = c.find(", ", at);
        comp.push_back(c.substr(at, next == std::string::npos ? std::string::npos : next - at));
        if (next == std::string::npos) break;
        at = next + 2;
      }
      while (comp.size() < 3) comp.push_back(names[comp.size()]);
    }
    for (int i = 0; i < probe.size; ++i)
      for (int j = i + 1; j < probe.size; ++j)
        candidates.push_back({"swapped-" + names[i] + names[j],
                              "is the solution's with its " + comp[i] + " and " + comp[j] +
                                  " exchanged: two components of a vector taken in the wrong order",
                              [i, j](const glm::vec3& p, int, int) {
                                glm::vec3 q = p;
                                std::swap(q[i], q[j]);
                                return q;
                              }});
    if (probe.size > 1)
      for (int i = 0; i < probe.size; ++i)
        candidates.push_back({"flipped-" + names[i],
                              "is the solution's with its " + comp[i] +
                                  " turned over: one component's sign (a convention or an axis) is the other way",
                              [i](const glm::vec3& p, int, int) {
                                glm::vec3 q = p;
                                q[i] = -q[i];
                                return q;
                              }});
    const Candidate* best = nullptr;
    double bestFit = kTableFit;
    for (auto& c : candidates) {
      if (c.kind == "scaled" && (std::abs(a - 1.0f) < 0.02f || std::abs(a + 1.0f) < 0.02f || std::abs(a) < 0.02f))
        continue;
      if (c.kind == "offset" && std::abs(b) < 1e-3f) continue;
      const double fit = t.residual(c.transform) / distance;
      if (fit < bestFit) {
        best = &c;
        bestFit = fit;
      }
    }
    if (best)
      out.push_back({"relation", best->kind, "On every input probed, " + result + " " + best->text + ".", bestFit});
  }

  // The solution's result scaled by a quantity of the inputs: the ratio, row by row, follows it.
  for (size_t k = 0; k < probe.quantities.size(); ++k) {
    const int qd = t.drawOf(FunctionProbe::Draw::Kind::Quantity, 0, int(k));
    std::vector<double> ratio, q;
    for (int r = 0; r < t.rows(); ++r) {
      const glm::vec3 s = t.at(student, t.base(0), r), p = t.at(solution, t.base(0), r);
      const float qv = solution.at(r, qd)[0];
      if (!Tables::finite(s) || !Tables::finite(p) || !std::isfinite(qv) || glm::length(p) < 1e-3f) continue;
      const double k1 = glm::dot(s, p) / glm::dot(p, p);
      if (glm::length(s - float(k1) * p) > 1e-3f * (1.0f + glm::length(s))) continue;  // not a multiple here
      ratio.push_back(k1);
      q.push_back(qv);
    }
    if (ratio.size() < size_t(probe.rows) / 4) continue;
    double spread = 0.0;
    for (double r : ratio) spread += (r - 1.0) * (r - 1.0);
    if (spread <= 1e-6 * double(ratio.size())) continue;  // the ratio is 1: no scaling
    struct Power {
      double e;
      bool positivePart;
      const char* text;
    };
    for (const Power& pw : {Power{1, false, "multiplied by"}, Power{-1, false, "divided by"},
                            Power{2, false, "multiplied by the square of"}, Power{1, true, "multiplied by"},
                            Power{-2, false, "divided by the square of"}}) {
      double miss = 0.0;
      bool ok = true;
      for (size_t i = 0; i < ratio.size() && ok; ++i) {
        const double base = pw.positivePart ? std::max(q[i], 0.0) : q[i];
        if (pw.e < 0 && std::abs(base) < 1e-3) continue;
        const double predicted = std::pow(base, pw.e);
        miss += (ratio[i] - predicted) * (ratio[i] - predicted);
      }
      const double fit = std::sqrt(miss / spread);
      if (ok && fit <= kTableFit) {
        out.push_back({"quantity", probe.quantities[k].name,
                       "On every input probed, " + result + " is the solution's " + pw.text + " " +
                           (pw.positivePart ? "the positive part of " : "") + probe.quantities[k].says + ".",
                       fit});
        break;
      }
    }
  }

  // Inputs the result ignores, or follows where the solution's does not.
  // Every ignored input in one finding: "Changing A or B changes ...".
  const auto units = probe.variedUnits();
  std::vector<std::string> ignoredNames, ignoredSays;
  size_t ignoredMoves = 0;
  for (size_t u = 0; u < units.size(); ++u) {
    const Tables::Moves m = t.moves(t.base(0), t.drawOf(FunctionProbe::Draw::Kind::Vary, 0, int(u)));
    if (m.solution >= m.rows / 4 && m.both * 20 <= m.solution) {
      ignoredNames.push_back(probe.unitName(int(u)));
      ignoredSays.push_back(probe.unitSays(int(u)));
      ignoredMoves = std::max(ignoredMoves, m.solution);
    } else if (m.solution * 100 <= m.rows && m.student >= m.rows / 4)
      out.push_back({"uses", probe.unitName(int(u)),
                     "Changing " + probe.unitSays(int(u)) + " changes " + result + " (on " + count(m.student, m.rows) +
                         " inputs probed), though the solution's does not depend on it.",
                     0.0});
  }
  if (!ignoredNames.empty()) {
    std::string names, says;
    for (size_t i = 0; i < ignoredNames.size(); ++i) {
      names += (i ? "+" : "") + ignoredNames[i];
      says += (i == 0 ? "" : i + 1 == ignoredSays.size() ? " or " : ", ") + ignoredSays[i];
    }
    out.push_back({"ignores", names,
                   "Changing " + says + " changes the solution's " + probe.says + " (on up to " +
                       count(ignoredMoves, size_t(probe.rows)) + " inputs probed) but not yours: " +
                       (ignoredSays.size() == 1 ? says + " does not" : "none of them does") + " reach your result.",
                   0.0});
  }
  for (size_t b = 1; b < probe.blocks.size(); ++b) {
    if (probe.blocks[b].varies.empty()) continue;
    const Tables::Moves m = t.moves(t.base(0), t.base(int(b)));
    if (m.solution >= m.rows / 4 && m.both * 20 <= m.solution)
      out.push_back({"ignores", probe.blocks[b].name,
                     "Changing " + probe.blocks[b].varies + " changes the solution's " + probe.says + " (on " +
                         count(m.solution, m.rows) + " inputs probed) but not yours: " + probe.blocks[b].varies +
                         " does not reach your result.",
                     0.0});
  }

  // Where the two differ: only in some blocks, or only at some edges.
  {
    const auto differing = [&](int block, int edge, size_t& n) {
      size_t d = 0;
      n = 0;
      for (int r = 0; r < t.rows(); ++r)
        if (t.edgeOf(r) == edge) {
          ++n;
          d += Tables::apart(t.at(student, t.base(block), r), t.at(solution, t.base(block), r));
        }
      return d;
    };
    size_t n = 0;
    bool labRowsAgree = true;
    std::vector<size_t> blocksDiffer;
    for (size_t b = 0; b < probe.blocks.size(); ++b) {
      const size_t d = differing(int(b), -1, n);
      if (d * 50 > n) {
        labRowsAgree = false;
        if (b > 0) blocksDiffer.push_back(b);
      }
    }
    const size_t first = differing(0, -1, n);
    if (first * 50 <= n) {
      std::vector<std::string> says, names;
      size_t shown = 0, of = 0;
      if (labRowsAgree) {
        for (size_t e = 0; e < probe.edges.size(); ++e) {
          size_t en = 0, d = 0;
          for (size_t b = 0; b < probe.blocks.size(); ++b) {
            size_t bn = 0;
            d += differing(int(b), int(e), bn);
            en += bn;
          }
          if (d * 10 >= en && d > 0) {
            says.push_back(probe.edges[e].says);
            names.push_back(probe.edges[e].name);
            shown += d;
            of += en;
          }
        }
      } else {
        for (size_t b : blocksDiffer) {
          says.push_back(probe.blocks[b].says);
          names.push_back(probe.blocks[b].name);
          shown += differing(int(b), -1, n);
          of += n;
        }
      }
      if (!says.empty()) {
        const std::string where = englishList(says, "");
        std::string key;
        for (size_t i = 0; i < says.size(); ++i) key += (i == 0 ? "" : "+") + names[i];
        out.push_back({"only", key,
                       "Your function's " + probe.says + " matches the solution's on the lab's inputs" +
                           (labRowsAgree ? "" : " with the lab's defaults") + " and differs only " + where + " (on " +
                           count(shown, of) + " such inputs probed): the cause lies in how your function handles " +
                           (says.size() == 1 ? "that case." : "those cases."),
                       0.0});
      }
    }
  }
  return out;
}

}  // namespace shadelab
