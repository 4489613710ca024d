#include "app/grade/diagnosis.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace shadelab {

namespace {

// A mistake's frame differs from the solution's in a configuration when they lie this far apart
// (frameDistance: RMS over covered pixels; one 8-bit step is 0.004).
constexpr double kDiffers = 0.004;
// It explains the student's frames when they lie at most this fraction of their distance to the
// solution from the mistake's, summed over the configurations where the mistake differs.
constexpr double kExplains = 0.5;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string fixed(double v, const char* format) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

bool lostPoints(const ConfigurationResult& c) {
  for (auto& r : c.checks)
    if (r.grade != Grade::Full) return true;
  return false;
}

// The result of the check `ref` names ("check" in `here`, or "configuration: check").
const CheckResult* findCheck(const ExerciseResult& e, const ConfigurationResult& here, const std::string& ref) {
  for (auto& c : e.configurations)
    if (ref.rfind(c.name + ": ", 0) == 0)
      for (auto& r : c.checks)
        if (r.check.name == ref.substr(c.name.size() + 2)) return &r;
  for (auto& r : here.checks)
    if (r.check.name == ref) return &r;
  return nullptr;
}

// A hint is kept only when the checks its cause needs passed in full or lost points as the
// rubric's "hint_when" says; messages that are not the hint (an error, a requirement) stay.
void silenceUnsupportedHints(ExerciseResult& e) {
  for (auto& c : e.configurations)
    for (auto& r : c.checks) {
      if (r.message.empty() || r.message != r.check.hint) continue;
      bool supported = true;
      for (auto& ref : r.check.hintIfPassed)
        if (const CheckResult* o = findCheck(e, c, ref); !o || o->grade != Grade::Full) supported = false;
      for (auto& ref : r.check.hintIfFailed)
        if (const CheckResult* o = findCheck(e, c, ref); !o || o->grade == Grade::Full) supported = false;
      if (!supported) r.message.clear();
    }
}

std::string nonFiniteCause(const ConfigurationResult& c) {
  std::string s = "Your frame holds non-finite values in " + quoted(c.name) + ": " + c.nonFiniteText + ". ";
  if (c.nanPixels)
    return s +
           "A NaN comes from 0/0 (an average over no samples), normalize() of a zero vector, or sqrt() or log() "
           "of a negative number: guard the case that makes the divisor or the length 0.";
  return s + "An Inf comes from dividing a non-zero value by 0 or from log(0): guard the divisor.";
}

// What a configuration's frame properties say, or "".
std::string propertyCause(const ConfigurationResult& c) {
  const std::string in = " in " + quoted(c.name);
  if (c.outOfRangePct > 0.5)
    return "Your values leave the view's range" + in + " (" + fixed(c.outOfRangePct, "%.1f") +
           " % of the pixels): a sum where an average was meant, or weights that do not add up to 1.";
  if (c.umbraLevel > 0.1)
    return "Where the truth and the solution are in full shadow, yours is not" + in + " (it averages " +
           fixed(c.umbraLevel, "%.2f") +
           " of the way to lit): an occluder closer than the receiver must count as in shadow.";
  if (c.litLevel > 0.1)
    return "Where the truth and the solution are fully lit, yours is not" + in + " (" + fixed(c.litLevel, "%.2f") +
           " of the way to shadow): surfaces shadow themselves (the bias) or the taps are scaled wrong.";
  if (c.edgeShiftX || c.edgeShiftY)
    return "Your edges" + in + " sit (" + std::to_string(c.edgeShiftX) + ", " + std::to_string(c.edgeShiftY) +
           ") pixels from the solution's: everything is offset, as by a sample grid that is not centred or a "
           "coordinate "
           "off by half a step.";
  if (c.edgeWidthRatio > 1.5 || c.edgeWidthRatio < 0.67)
    return "Your soft edges" + in + " are " + fixed(c.edgeWidthRatio, "%.2f") +
           " times as wide as the solution's: the filter's footprint is " +
           (c.edgeWidthRatio > 1.0 ? "too large" : "too small") + " (its size, or the scale of its offsets).";
  return {};
}

}  // namespace

int explainingMistake(const Exercise& ex, const ExerciseResult& e) {
  int best = -1;
  double bestRatio = kExplains;
  for (size_t k = 0; k < ex.mistakes.size(); ++k) {
    double toMistake = 0.0, toSolution = 0.0;
    bool differs = false;
    for (auto& c : e.configurations) {
      if (!c.drawn || k >= c.mistakeDistances.size() || k >= c.mistakeSeparations.size()) continue;
      if (c.mistakeSeparations[k] <= kDiffers) continue;
      differs = true;
      toMistake += c.mistakeDistances[k];
      toSolution += c.distance;
    }
    if (!differs || toSolution <= 0.0) continue;
    if (const double ratio = toMistake / toSolution; ratio <= bestRatio) {
      best = int(k);
      bestRatio = ratio;
    }
  }
  return best;
}

void diagnose(const Exercise& ex, ExerciseResult& e) {
  silenceUnsupportedHints(e);
  e.diagnosis.clear();
  e.mistake.clear();
  if (e.total > 0.0 && e.earned >= e.total - 1e-9) return;

  switch (e.outcome()) {
    case Outcome::NotSubmitted:
      e.diagnosis = "Not submitted: " + (e.missingFiles.empty() ? std::string("no file") : e.missingFiles.front()) +
                    " is in none of the folders graded.";
      return;
    case Outcome::DidNotBuild:
      for (auto& c : e.configurations)
        if (!c.errors.empty()) {
          // The message without its file and line, which the error itself shows below.
          std::string first = c.errors.front().substr(0, c.errors.front().find('\n'));
          if (const size_t at = first.find("error: "); at != std::string::npos) first = first.substr(at + 7);
          e.diagnosis = "Your shader does not build (" + first +
                        "; the error is shown at its file and line). Nothing "
                        "it draws can be scored.";
          return;
        }
      break;
    case Outcome::TimedOut:
      e.diagnosis =
          "Your shader ran too long and was stopped: a loop whose bound is never reached (a condition that "
          "stays true, a counter that does not move).";
      return;
    case Outcome::Crashed:
      e.diagnosis = "The renderer crashed drawing your shader; nothing it drew could be scored.";
      return;
    case Outcome::Graded:
      break;
  }

  if (const int k = explainingMistake(ex, e); k >= 0) {
    e.mistake = ex.mistakes[size_t(k)].name;
    e.diagnosis = ex.mistakes[size_t(k)].diagnosis;
    return;
  }
  for (auto& c : e.configurations)
    if (c.nanPixels + c.infPixels > 0) {
      e.diagnosis = nonFiniteCause(c);
      return;
    }
  for (auto& c : e.configurations)
    if (lostPoints(c))
      if (std::string cause = propertyCause(c); !cause.empty()) {
        e.diagnosis = cause;
        return;
      }
  const ConfigurationResult* only = nullptr;
  int losing = 0;
  for (auto& c : e.configurations)
    if (lostPoints(c)) {
      ++losing;
      only = &c;
    }
  if (losing == 1 && e.configurations.size() > 1) {
    e.diagnosis = "Only " + quoted(only->name) +
                  " loses points; in the other configurations your frames match the "
                  "solution's. The cause lies in what this one alone uses: " +
                  only->description + ".";
    return;
  }
  const CheckResult* worst = nullptr;
  const ConfigurationResult* where = nullptr;
  for (auto& c : e.configurations)
    for (auto& r : c.checks)
      if (!worst || r.check.points - r.earned > worst->check.points - worst->earned) {
        worst = &r;
        where = &c;
      }
  e.diagnosis = "No known mistake matches your frames; the check that lost most is " +
                quoted(where->name + ": " + worst->check.name) + " (" + worst->check.metric + " " +
                (std::isfinite(worst->value) ? fixed(worst->value, "%.4g") : std::string("n/a")) +
                ", full marks at <= " + fixed(worst->fullBound, "%.4g") + ").";
}

}  // namespace shadelab
