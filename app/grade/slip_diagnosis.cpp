#include "app/grade/slip_diagnosis.h"

#include <algorithm>
#include <set>

#include "app/grade/diagnosis.h"
#include "app/grade/frame_properties.h"

namespace shadelab {

namespace {

// Whether the student's frames are slip `index`'s (grade/configuration_frames.h: drawSlips): in every
// drawn configuration where the student's frame differs from the solution's the slip's does too,
// and wherever the slip's differs the student's is its frame. `misfit`: the summed distance to the
// slip's frames over the summed distance to the solution's, where it shows; `where` the
// configurations it shows in.
bool slipAgrees(const ExerciseResult& e, int index, double& misfit, std::vector<std::string>& where) {
  double toSlip = 0.0, toSolution = 0.0;
  where.clear();
  for (auto& c : e.configurations) {
    if (!c.drawn) continue;
    if (!c.slipsDrawn) return false;
    const auto it = std::find_if(c.slips.begin(), c.slips.end(),
                                 [&](const ConfigurationResult::Slip& s) { return s.index == index; });
    if (it == c.slips.end()) {  // the slip draws the solution's frame here
      if (c.slipBase > kFramesDiffer) return false;
      continue;
    }
    // Where the student's frame holds NaN or Inf, only the slip's own frame will do: a few such
    // pixels weigh little in a distance, and a slip without them would hide them.
    const bool nonFinite =
        c.nanPixels + c.infPixels > 0 || std::any_of(c.probeFindings.begin(), c.probeFindings.end(),
                                                     [](const ProbeFinding& f) { return f.kind == "non-finite"; });
    if (it->distance > (nonFinite ? kFramesDiffer : std::max(kFramesDiffer, kSlipFits * c.slipBase))) return false;
    toSlip += it->distance;
    toSolution += c.slipBase;
    where.push_back(c.name);
  }
  if (where.empty() || toSolution <= 0.0) return false;
  misfit = toSlip / toSolution;
  return true;
}

}  // namespace

SlipFinding findSlip(const Exercise& ex, const ExerciseResult& e) {
  struct Fit {
    double misfit;
    const ConfigurationResult::Slip* slip;
    std::vector<std::string> where;
  };
  std::vector<Fit> fits;
  std::set<int> seen;
  for (auto& c : e.configurations)
    for (auto& s : c.slips)
      if (seen.insert(s.index).second)
        if (Fit f{0.0, &s, {}}; slipAgrees(e, s.index, f.misfit, f.where)) fits.push_back(std::move(f));
  if (fits.empty()) return {};
  std::sort(fits.begin(), fits.end(), [](const Fit& a, const Fit& b) { return a.misfit < b.misfit; });
  // The different causes of the slips that fit about as well as the best, each with its fix where
  // the rubric reveals fixes and every slip of that cause has the same one (a difference of two
  // samples made zero by either sign turned round has a cause, but no one fix).
  std::vector<std::pair<std::string, std::string>> causes;  // cause, and its fix or ""
  const std::vector<std::string>& where = fits.front().where;
  for (auto& f : fits) {
    if (f.misfit > kDiagnosisClose * fits.front().misfit + kDiagnosisSlack) break;
    const auto it = std::find_if(causes.begin(), causes.end(), [&](const auto& c) { return c.first == f.slip->cause; });
    if (it == causes.end())
      causes.push_back({f.slip->cause, f.slip->causeAndFix});
    else if (it->second != f.slip->causeAndFix)
      it->second.clear();
  }
  if (causes.size() > 2) return {};
  const bool withFix = ex.reveal == "cause-and-fix";
  const auto said = [&](const std::pair<std::string, std::string>& c) {
    return withFix && !c.second.empty() ? c.second : c.first;
  };
  SlipFinding out;
  out.tag = "slip:" + fits.front().slip->kind;
  out.misfit = fits.front().misfit;
  out.what = causes.size() == 1 ? "one slip: " + said(causes[0]) + "."
                                : "one slip, and two slips draw them alike: either " + said(causes[0]) + ", or " +
                                      said(causes[1]) + ".";
  const size_t drawn = size_t(std::count_if(e.configurations.begin(), e.configurations.end(),
                                            [](const ConfigurationResult& c) { return c.drawn; }));
  // NaN or Inf in the student's frames that the slip's hold too (slipAgrees asks for its very
  // frame there): the slip is where they come from, and the student is told so.
  std::string nonFinite;
  for (auto& c : e.configurations)
    if (c.drawn && !c.nonFiniteText.empty() && std::find(where.begin(), where.end(), c.name) != where.end()) {
      nonFinite = ", NaN and Inf included ('" + c.name + "': " + c.nonFiniteText + ")";
      break;
    }
  const bool exact = out.misfit <= kDiagnosisSlack;
  out.evidence = " Your code may be written otherwise, but it has this effect. (Evidence: where the slip shows, in " +
                 quotedList(where) + ", your frames " +
                 (exact ? "are its frames" : "lie far closer to its frames than to the solution's") + nonFinite +
                 (where.size() < drawn ? "; where it draws the solution's frames, so do yours.)" : ".)");
  return out;
}

}  // namespace shadelab
