#include "app/grade/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "app/grade/frame_causes.h"
#include "app/grade/hints.h"
#include "app/grade/slip_diagnosis.h"
#include "app/util/format.h"

namespace shadelab {

namespace {

constexpr double kDiffers = kFramesDiffer;
// A mistake's frame explains the student's in a configuration when the student's lies at most
// this fraction of its distance to the solution from the mistake's.
constexpr double kExplains = 0.5;
// Two explanations fit about as well (diagnosis.h), by shorter names.
constexpr double kClose = kDiagnosisClose, kSlack = kDiagnosisSlack;
// A relation to the solution's frames (grade/frame_relations.h) wins over a listed mistake when
// its residual is at most this fraction of the student's distance to the mistake's frames.
constexpr double kRelationWins = 0.5;

bool lostPoints(const ConfigurationResult& c) {
  for (auto& r : c.checks)
    if (r.grade != Grade::Full) return true;
  return false;
}

// The configurations a diagnosis reasons over: those drawn, split by whether they lost points.
struct Evidence {
  const Exercise& ex;
  const ExerciseResult& e;
  std::vector<const ConfigurationResult*> losing, matching;

  std::vector<const ConfigurationResult*> losingProbes;  // the losing configurations whose view is a probe
  std::vector<const ConfigurationResult*> functions;     // the function probed by itself (no checks)

  Evidence(const Exercise& x, const ExerciseResult& r) : ex(x), e(r) {
    for (auto& c : e.configurations)
      if (c.drawn && c.function)
        functions.push_back(&c);
      else if (c.drawn)
        (lostPoints(c) ? losing : matching).push_back(&c);
    for (auto* c : losing)
      if (const Configuration* rc = rubricOf(*c); rc && rc->probe) losingProbes.push_back(c);
  }
  // Where a relation must hold: the losing configurations whose view draws the function's result,
  // when there are any (a relation of the function need not survive the shading around it), else
  // every losing configuration.
  const std::vector<const ConfigurationResult*>& related() const {
    return losingProbes.empty() ? losing : losingProbes;
  }
  const Configuration* rubricOf(const ConfigurationResult& c) const {
    for (auto& rc : ex.configurations)
      if (rc.name == c.name) return &rc;
    return nullptr;
  }
  ViewRange range(const ConfigurationResult& c) const {
    const Configuration* rc = rubricOf(c);
    return rc ? ViewRange{rc->bounded, rc->low, rc->high} : ViewRange{};
  }
  std::string channels(const ConfigurationResult& c) const {
    const Configuration* rc = rubricOf(c);
    return rc ? rc->channels : "red, green, blue";
  }
};

bool differs(const ConfigurationResult& c, size_t k) {
  return k < c.mistakeSeparations.size() && k < c.mistakeDistances.size() && c.mistakeSeparations[k] > kDiffers;
}

// Whether mistake k's frames are the student's where it shows, and nowhere else is the student
// wrong: the student loses points only where the mistake differs from the solution, and in every
// configuration where it differs, the student's frame lies close to the mistake's. The misfit
// (summed distance to the mistake's frames over the summed distance to the solution's) in `misfit`.
bool agrees(const Evidence& ev, size_t k, double& misfit) {
  double toMistake = 0.0, toSolution = 0.0;
  bool shows = false;
  for (auto* c : ev.losing)  // a configuration whose frame is the solution's lost points on a truth's number
    if (c->distance > kDiffers && !differs(*c, k)) return false;
  for (auto* c : ev.functions)  // the student's function differs where the mistake's does not
    if (c->distance > kDiffers && !differs(*c, k)) return false;
  for (auto& c : ev.e.configurations) {
    if (!c.drawn || !differs(c, k)) continue;
    if (c.mistakeDistances[k] > kExplains * c.distance) return false;
    shows = true;
    toMistake += c.mistakeDistances[k];
    toSolution += c.distance;
  }
  if (!shows || toSolution <= 0.0) return false;
  misfit = toMistake / toSolution;
  return true;
}

// The student's frame to mistakes k and j made together, in configuration c (NaN when not drawn).
double pairDistance(const ConfigurationResult& c, size_t k, size_t j) {
  for (auto& p : c.pairDistances)
    if ((p.a == k && p.b == j) || (p.a == j && p.b == k)) return p.distance;
  return std::nan("");
}

// Two mistakes made together: every losing configuration is one where either differs; where one
// shows alone the student's frame is that mistake's, where both show it is the two together
// (grade/frame_relations.h: composeChanges), and each shows somewhere.
bool agreeTogether(const Evidence& ev, size_t k, size_t j, double& misfit) {
  double toMistakes = 0.0, toSolution = 0.0;
  for (auto* c : ev.losing)
    if (c->distance > kDiffers && !differs(*c, k) && !differs(*c, j)) return false;
  for (auto& c : ev.e.configurations) {
    if (!c.drawn || (!differs(c, k) && !differs(c, j))) continue;
    const double d = differs(c, k) && differs(c, j) ? pairDistance(c, k, j)
                     : differs(c, k)                ? c.mistakeDistances[k]
                                                    : c.mistakeDistances[j];
    if (!(d <= kExplains * c.distance)) return false;
    toMistakes += d;
    toSolution += c.distance;
  }
  if (toSolution <= 0.0) return false;
  misfit = toMistakes / toSolution;
  return true;
}

// The relation that holds in every losing configuration (the same kind, and the same numbers),
// or none; `misfit` its summed residual over the summed distance.
bool commonRelation(const Evidence& ev, FrameRelation& out, double& residualSum, double& misfit) {
  const std::vector<const ConfigurationResult*>& where = ev.related();
  if (where.empty()) return false;
  for (auto& candidate : where.front()->relations) {
    double residual = 0.0, distance = 0.0;
    bool everywhere = true;
    for (auto* c : where) {
      const auto it = std::find_if(c->relations.begin(), c->relations.end(),
                                   [&](const FrameRelation& r) { return sameRelation(r, candidate); });
      if (it == c->relations.end()) {
        everywhere = false;
        break;
      }
      residual += it->residual;
      distance += c->distance;
    }
    if (everywhere && distance > 0.0) {
      out = candidate;
      residualSum = residual;
      misfit = residual / distance;
      return true;  // relations are listed best first
    }
  }
  return false;
}

// The setting that draws the student's frames in every losing configuration when the solution is
// drawn with it at another value (grade/configuration_frames.h); `misfit` as for a relation.
bool commonSetting(const Evidence& ev, std::string& key, std::vector<std::string>& values, double& misfit) {
  if (ev.losing.empty()) return false;
  for (auto& candidate : ev.losing.front()->settingMatches) {
    double residual = 0.0, distance = 0.0;
    std::vector<std::string> seen;
    for (auto* c : ev.losing) {
      const auto it = std::find_if(c->settingMatches.begin(), c->settingMatches.end(),
                                   [&](const ConfigurationResult::SettingMatch& m) { return m.key == candidate.key; });
      if (it == c->settingMatches.end()) break;
      residual += it->distance;
      distance += c->distance;
      seen.push_back(it->value);
    }
    if (seen.size() == ev.losing.size() && distance > 0.0) {
      key = candidate.key;
      values = seen;
      misfit = residual / distance;
      return true;
    }
  }
  return false;
}

std::string settingSentence(const Evidence& ev, const std::string& key, const std::vector<std::string>& values) {
  std::vector<std::string> where, asIf, given;
  bool unused = true;
  for (size_t i = 0; i < ev.losing.size(); ++i) {
    const ConfigurationResult& c = *ev.losing[i];
    where.push_back(c.name);
    const std::string& v = values[i];
    const std::string shown = v.empty() ? "the lab's default" : v;
    if (std::find(asIf.begin(), asIf.end(), shown) == asIf.end()) asIf.push_back(shown);
    // The lab's default, 0, 1 or a value another configuration sets: the setting is not used (a
    // literal stands in its place); half, twice or the reciprocal: it is used at another strength.
    bool elsewhere = false;
    for (auto& rc : ev.ex.configurations)
      for (auto& [k, value] : rc.settings) elsewhere = elsewhere || (k == key && value == v);
    unused = unused && (v.empty() || v == "0" || v == "1" || elsewhere);
    if (const Configuration* rc = ev.rubricOf(c))
      for (auto& [k, value] : rc->settings)
        if (k == key && std::find(given.begin(), given.end(), value) == given.end()) given.push_back(value);
  }
  std::string as, set;
  for (auto& v : asIf) as += (as.empty() ? "" : " or ") + v;
  for (auto& v : given) set += (set.empty() ? "" : " and ") + v;
  std::string s = "Your frames in " + quotedList(where) + " are the solution's drawn with " + key + " at " + as +
                  " (the configuration sets " + set + "): ";
  return s + (unused ? "your result does not use " + key +
                           " (a fixed value stands in its place), or uses it where it "
                           "has no effect."
                     : "your result uses " + key + " at another strength than it has (applied twice, or halved).");
}

// The student's summed distance to mistake k's frames over the configurations where they lose
// points: what a relation's residual is compared with.
double distanceToMistake(const Evidence& ev, size_t k) {
  double d = 0.0;
  for (auto* c : ev.related()) d += k < c->mistakeDistances.size() ? c->mistakeDistances[k] : c->distance;
  return d;
}

// Where the frames differ, as a setting of the rubric's configurations: the keys whose values in
// the losing configurations are one value no matching configuration has. `tag` receives
// "where:KEY=VALUE", or "only:NAME" when one configuration loses and no setting sets it apart.
std::string wherePredicate(const Evidence& ev, std::string& tag) {
  if (ev.losing.empty() || ev.matching.empty()) return {};
  std::vector<std::string> losingNames, matchingNames;
  for (auto* c : ev.losing) losingNames.push_back(c->name);
  for (auto* c : ev.matching) matchingNames.push_back(c->name);
  // Every configuration's settings as key -> value, with its scene and camera.
  const auto settingsOf = [&](const ConfigurationResult& c) {
    std::map<std::string, std::string> s;
    if (const Configuration* rc = ev.rubricOf(c)) {
      s["scene"] = rc->scene.empty() ? "(the lab's default)" : rc->scene;
      if (!rc->camera.empty()) s["camera"] = rc->camera;
      for (auto& [key, value] : rc->settings) s[key] = value;
    }
    return s;
  };
  std::vector<std::string> keys;  // in the order the rubric sets them
  for (auto& rc : ev.ex.configurations)
    for (auto& [key, value] : rc.settings)
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  for (const char* key : {"scene", "camera"}) keys.push_back(key);
  std::string separating;  // "green is directx and normal_strength is 2.5 or 1.5"
  for (auto& key : keys) {
    std::vector<std::string> inLosing;  // in the order the configurations come
    std::set<std::string> inMatching;
    const auto value = [&](const ConfigurationResult& c) {
      auto s = settingsOf(c);
      return s.count(key) ? s[key] : std::string("left at the lab's default");
    };
    for (auto* c : ev.losing)
      if (std::find(inLosing.begin(), inLosing.end(), value(*c)) == inLosing.end()) inLosing.push_back(value(*c));
    for (auto* c : ev.matching) inMatching.insert(value(*c));
    if (std::any_of(inLosing.begin(), inLosing.end(), [&](const std::string& v) { return inMatching.count(v) > 0; }))
      continue;
    // Several values set apart only from one matching configuration say little: everything differs
    // from a single configuration in something.
    if (inLosing.size() > 1 && ev.matching.size() < 2) continue;
    if (tag.empty()) tag = "where:" + key + (inLosing.size() == 1 ? "=" + inLosing.front() : "");
    std::string values;
    for (auto& v : inLosing) values += (values.empty() ? "" : " or ") + v;
    separating += (separating.empty() ? "" : " and ") + key + " is " + values;
  }
  if (!separating.empty())
    return "Your frames match the solution's in " + quotedList(matchingNames) + " and differ only where " + separating +
           " (" + quotedList(losingNames) + "): the cause lies in what " +
           (separating.find(" and ") == std::string::npos ? "that setting changes." : "those settings change.");
  if (ev.losing.size() == 1) {
    tag = "only:" + ev.losing.front()->name;
    return "Only " + quoted(ev.losing.front()->name) +
           " loses points; in the other configurations your frames match the solution's. The cause lies in what "
           "this one alone uses: " +
           ev.losing.front()->description + ".";
  }
  return {};
}

std::string mistakeSentence(const Exercise& ex, const Mistake& m) {
  return m.diagnosis + (ex.reveal == "cause-and-fix" && !m.fix.empty() ? " " + m.fix : "");
}

// Whether the student's frames are mistake k's wherever it shows (within one 8-bit step), not
// merely close to them.
bool exactly(const ExerciseResult& e, size_t k) {
  for (auto& c : e.configurations)
    if (c.drawn && differs(c, k) && c.mistakeDistances[k] > kDiffers) return false;
  return true;
}

// "(Evidence: where this mistake shows, in 'a' and 'b', your frames are its frames.)"
std::string mistakeEvidence(const ExerciseResult& e, size_t k) {
  std::vector<std::string> where;
  for (auto& c : e.configurations)
    if (c.drawn && differs(c, k)) where.push_back(c.name);
  return " (Evidence: where this mistake shows, in " + quotedList(where) + ", your frames " +
         (exactly(e, k) ? "are its frames" : "lie far closer to its frames than to the solution's") + ".)";
}

std::string relationSentence(const Evidence& ev, const FrameRelation& r) {
  const ConfigurationResult& first = *ev.related().front();
  std::vector<std::string> where;
  for (auto* c : ev.related()) where.push_back(c->name);
  std::string s = "Your frames are " + describeRelation(r, ev.range(first), ev.channels(first));
  if (!ev.losingProbes.empty())
    s += " in " + quotedList(where) + ", where the view draws your function's result itself";
  else
    s += ev.matching.empty() ? " in every configuration" : " in " + quotedList(where) + " (the others match)";
  return s + ": " + relationCause(r) + ".";
}

// The first finding of `kind` in the function's tables, and the configuration it comes from.
std::pair<const ProbeFinding*, const ConfigurationResult*> probeFinding(const Evidence& ev, const std::string& kind) {
  for (auto* c : ev.functions)
    for (auto& f : c->probeFindings)
      if (f.kind == kind) return {&f, c};
  return {nullptr, nullptr};
}

// What the frames show when no explanation stands: how many configurations differ, where most.
std::string evidenceSentence(const Evidence& ev) {
  const ConfigurationResult* most = nullptr;
  for (auto* c : ev.losing)
    if (!most || c->distance > most->distance) most = c;
  std::string s =
      "No known mistake and no simple relation to the solution's frames (turned over, scaled, offset, "
      "mirrored, shifted, components exchanged) explains yours.";
  if (most)
    s += " They differ in " + std::to_string(ev.losing.size()) + " of " +
         std::to_string(ev.losing.size() + ev.matching.size()) + " configurations, most in " + quoted(most->name) +
         " (RMS difference " + formatFixed(most->distance, 3) + ").";
  return s;
}

}  // namespace

int explainingMistake(const Exercise& ex, const ExerciseResult& e) {
  const Evidence ev(ex, e);
  int best = -1;
  double bestMisfit = 0.0;
  for (size_t k = 0; k < ex.mistakes.size(); ++k)
    if (double misfit; agrees(ev, k, misfit) && (best < 0 || misfit < bestMisfit)) {
      best = int(k);
      bestMisfit = misfit;
    }
  return best;
}

namespace {

void diagnoseFromEvidence(const Exercise& ex, ExerciseResult& e) {
  silenceUnsupportedHints(e);
  e.diagnosis.clear();
  e.mistake.clear();
  e.explanation.clear();
  if (e.total > 0.0 && e.earned >= e.total - 1e-9) return;

  switch (e.outcome()) {
    case Outcome::NotSubmitted:
      e.explanation = "not-submitted";
      e.diagnosis = "Not submitted: " + (e.missingFiles.empty() ? std::string("no file") : e.missingFiles.front()) +
                    " is in none of the folders graded.";
      return;
    case Outcome::DidNotBuild:
      for (auto& c : e.configurations)
        if (!c.errors.empty()) {
          // The message without its file and line, which the error itself shows below.
          std::string first = c.errors.front().substr(0, c.errors.front().find('\n'));
          if (const size_t at = first.find("error: "); at != std::string::npos) first = first.substr(at + 7);
          e.explanation = "did-not-build";
          e.diagnosis = "Your shader does not build (" + first +
                        "; the error is shown at its file and line). Nothing "
                        "it draws can be scored.";
          return;
        }
      break;
    case Outcome::TimedOut:
      e.explanation = "timed-out";
      e.diagnosis =
          "Your shader ran too long and was stopped: a loop whose bound is never reached (a condition that "
          "stays true, a counter that does not move).";
      return;
    case Outcome::Crashed:
      e.explanation = "crashed";
      e.diagnosis = "The renderer crashed drawing your shader; nothing it drew could be scored.";
      return;
    case Outcome::Graded:
      break;
  }

  const Evidence ev(ex, e);
  // The listed mistakes whose frames agree with the student's, best first.
  std::vector<std::pair<double, size_t>> agreeing;
  for (size_t k = 0; k < ex.mistakes.size(); ++k)
    if (double misfit; agrees(ev, k, misfit)) agreeing.push_back({misfit, k});
  std::sort(agreeing.begin(), agreeing.end());
  // A changed file whose frames are exactly the starter's and a listed mistake's: the mistake says
  // how (a slope scaled to nothing draws the starter's flat normals).
  if (!e.starterUnchanged && std::any_of(agreeing.begin(), agreeing.end(), [&](const auto& a) {
        return !ex.mistakes[a.second].starter && exactly(e, a.second);
      }))
    agreeing.erase(
        std::remove_if(agreeing.begin(), agreeing.end(), [&](const auto& a) { return ex.mistakes[a.second].starter; }),
        agreeing.end());
  FrameRelation relation;
  double relationResidual = 0.0, relationMisfit = 0.0;  // summed where it must hold; over the distance
  const bool related = commonRelation(ev, relation, relationResidual, relationMisfit);
  const SlipFinding slip = findSlip(ex, e);
  // The student's own code traced beside the solution's (the function probed by itself, else in the
  // lab's draw where the frames differ most): the line where their values part. It states only
  // what the values show, so it stands before any cause read from frames that are merely close to
  // a mistake's, a slip's or a relation's.
  // A trace whose line does not stand out (TraceFinding::isolated) is said only where nothing
  // but a guess would be.
  const ConfigurationResult *traced = nullptr, *loose = nullptr;
  for (auto* c : ev.functions)
    if (!traced && c->trace.isolated()) traced = c;
  for (auto& c : e.configurations)
    if (!traced && c.trace.isolated()) traced = &c;
  for (auto& c : e.configurations)
    if (!loose && c.trace.found) loose = &c;
  const auto sayTrace = [&](const ConfigurationResult& c) {
    e.explanation = c.trace.tag();
    e.diagnosis = c.trace.text + " (Evidence: " + c.trace.evidence(c.name) + ".)";
  };

  if (!agreeing.empty()) {
    const size_t k = agreeing.front().second;
    const Mistake& m = ex.mistakes[k];
    // A relation, or a slip of the solution, whose frames are far closer to the student's than a
    // mistake's that is only close to them.
    const bool closerFitElsewhere =
        (related && relationResidual <= kRelationWins * distanceToMistake(ev, k) && !m.starter) ||
        (slip.found() && !m.starter && !exactly(e, k) && slip.misfit <= kRelationWins * agreeing.front().first);
    // A second mistake fits about as well, and the first is not the only one whose frames the
    // student's are exactly.
    const bool split = agreeing.size() > 1 && agreeing[1].first <= kClose * agreeing.front().first + kSlack &&
                       (!exactly(e, k) || exactly(e, agreeing[1].second));
    if (m.starter && !closerFitElsewhere) {
      // A changed file that draws the starter's frames: what it draws is known, why is not (a
      // constant returned for a reason of its own, a value read the wrong way round): the trace
      // says where its values part, where there is one.
      e.mistake = m.name;
      e.explanation = e.starterUnchanged ? "starter" : "starter-result";
      e.diagnosis = e.starterUnchanged ? m.diagnosis
                                       : "Your frames are the starter's, though your file is not: what you wrote "
                                         "draws exactly what the placeholder draws.";
      if (!e.starterUnchanged && traced) {
        const std::string seen = e.diagnosis;
        sayTrace(*traced);
        e.diagnosis = seen + " " + e.diagnosis;
      }
      return;
    }
    if (related && !m.starter && exactly(e, k) && relationResidual <= kDiffers * double(ev.losing.size())) {
      // The mistake is itself a relation of the solution (a comparison inverted turns every frame
      // over): say the relation, which is what the frames show, and the mistake as one way to it.
      e.mistake = m.name;
      e.explanation = "relation:" + relation.kind;
      e.diagnosis =
          relationSentence(ev, relation) + " A known mistake draws exactly these frames: " + mistakeSentence(ex, m);
      return;
    }
    if (!closerFitElsewhere && !split && exactly(e, k) && !m.starter)
      if (auto [finding, probe] = probeFinding(ev, "ignores"); finding) {
        // The mistake's code is one way to ignore an input; the student's may be another (the
        // strength left out draws what the strength applied to every component draws): say what
        // the function's table shows, and the mistake as one way to it.
        e.mistake = m.name;
        e.explanation = "probe:ignores:" + finding->key;
        e.diagnosis = finding->text + " (Evidence: " + quoted(probe->name) +
                      ".) A known mistake returns exactly these values: " + mistakeSentence(ex, m);
        return;
      }
    if (!closerFitElsewhere && !split) {
      // Frames that are the mistake's name it; frames only close to them say so: the effect is the
      // mistake's, the code that makes it may differ (a bias far too small acts as none). Where the
      // student's code is traced, its own line says more than a likeness.
      const bool exact = exactly(e, k);
      if (!exact && traced) {
        sayTrace(*traced);
        return;
      }
      e.mistake = m.name;
      e.explanation = (exact ? "mistake:" : "like:") + m.name;
      e.diagnosis = (exact ? "" : "Your frames come close to what a known mistake draws, so its effect is yours: ") +
                    mistakeSentence(ex, m) + mistakeEvidence(e, k);
      return;
    }
    if (!closerFitElsewhere) {  // two listed mistakes fit about as well: say what the frames show
      std::string tag, where = wherePredicate(ev, tag);
      e.explanation = "evidence";
      e.diagnosis = (where.empty() ? "" : where + " ") +
                    "Your frames lie about as close to the frames of two "
                    "known mistakes, so the evidence cannot tell which you made; compare your frame with the "
                    "solution's where they differ.";
      return;
    }
  }
  // Two listed mistakes together are a likeness of frames: where the student's own code is traced,
  // its line is what the evidence shows.
  if (agreeing.empty() && !traced)
    for (size_t k = 1; k < ex.mistakes.size(); ++k)
      for (size_t j = k + 1; j < ex.mistakes.size(); ++j)
        if (double misfit; agreeTogether(ev, k, j, misfit)) {
          e.explanation = "mistakes:" + ex.mistakes[k].name + "+" + ex.mistakes[j].name;
          e.diagnosis = "Two causes together. " + mistakeSentence(ex, ex.mistakes[k]) + mistakeEvidence(e, k) +
                        " And: " + mistakeSentence(ex, ex.mistakes[j]) + mistakeEvidence(e, j);
          return;
        }
  // One slip of the solution draws the student's frames: no list of mistakes needed. When a
  // relation to the solution's frames holds as exactly, the relation is what the frames show and
  // the slip one way to it.
  if (slip.found()) {
    // What the frames show comes first when a relation or a setting draws them as exactly: a slip is
    // one way to that effect, and the student's code may be another (the strength applied to z
    // draws what the strength dividing x and y draws).
    std::string key;
    std::vector<std::string> values;
    double settingMisfit = 0.0;
    const std::string also = " They are also the solution's with " + slip.what + slip.evidence;
    if (related && relationResidual <= kDiffers * double(ev.related().size())) {
      e.explanation = "relation:" + relation.kind;
      e.diagnosis = relationSentence(ev, relation) + also;
    } else if (commonSetting(ev, key, values, settingMisfit) && settingMisfit <= kSlipFits) {
      e.explanation = "setting:" + key;
      e.diagnosis = settingSentence(ev, key, values) + also;
    } else {
      e.explanation = slip.tag;
      e.diagnosis = "Your frames are the solution's with " + slip.what + slip.evidence;
    }
    // A slip that draws the student's frames exactly is one edit from the solution: its kind
    // names the cause. The trace adds where the student's own values part.
    if (traced)
      e.diagnosis += " Traced line by line" + std::string(traced->trace.inDraw() ? " in the lab's draw" : "") + ": " +
                     traced->trace.text;
    return;
  }
  if (traced) {
    sayTrace(*traced);
    return;
  }
  // The function probed by itself: what its table says, before what the pictures made of it say.
  // The most telling finding of any probe (findingRank): an input turned round or ignored says
  // more than a where.
  const ProbeFinding* told = nullptr;
  const ConfigurationResult* toldBy = nullptr;
  for (auto* c : ev.functions)
    for (auto& f : c->probeFindings)
      if (findingRank(f.kind) >= 0 && (!told || findingRank(f.kind) < findingRank(told->kind))) {
        told = &f;
        toldBy = c;
      }
  if (told) {
    e.explanation = "probe:" + told->kind + (told->key.empty() ? "" : ":" + told->key);
    e.diagnosis = told->text + " (Evidence: your function and the solution's, each evaluated by itself on the " +
                  "same table of inputs, " + quoted(toldBy->name) + ".)";
    return;
  }
  for (auto& c : e.configurations)
    if (c.nanPixels + c.infPixels > 0) {
      e.explanation = "non-finite";
      e.diagnosis = nonFiniteCause(c);
      return;
    }
  std::string settingKey;
  std::vector<std::string> settingValues;
  double settingMisfit = 0.0;
  if (commonSetting(ev, settingKey, settingValues, settingMisfit) && !(related && relationMisfit < settingMisfit)) {
    e.explanation = "setting:" + settingKey;
    e.diagnosis = settingSentence(ev, settingKey, settingValues);
    return;
  }
  if (related) {
    e.explanation = "relation:" + relation.kind;
    std::string tag, where = wherePredicate(ev, tag);
    e.diagnosis = relationSentence(ev, relation) + (where.empty() ? "" : " " + where);
    return;
  }
  // A setting that sets the losing configurations apart is evidence; a property's usual cause is a
  // guess, so where the setting is known only what the property measures is added.
  std::string whereTag, where = wherePredicate(ev, whereTag);
  if (whereTag.rfind("where:", 0) == 0) {
    e.explanation = whereTag;
    e.diagnosis = where;
    for (auto* c : ev.losing)
      if (std::string seen = propertyObservation(*c, ev.range(*c)); !seen.empty()) {
        e.diagnosis += " " + seen;
        break;
      }
    return;
  }
  if (loose) {  // what the student's values show, before a property's usual cause
    sayTrace(*loose);
    return;
  }
  for (auto* c : ev.losing)
    if (Cause cause = propertyCause(*c, ev.range(*c)); !cause.text.empty()) {
      e.explanation = cause.tag;
      e.diagnosis = cause.text;
      return;
    }
  if (!where.empty()) {
    e.explanation = whereTag;
    e.diagnosis = where;
    return;
  }
  const CheckResult* worst = nullptr;
  const ConfigurationResult* at = nullptr;
  for (auto& c : e.configurations)
    for (auto& r : c.checks)
      if (!worst || r.check.points - r.earned > worst->check.points - worst->earned) {
        worst = &r;
        at = &c;
      }
  e.explanation = "evidence";
  e.diagnosis = evidenceSentence(ev);
  if (worst)
    e.diagnosis += " The check that lost most is " + quoted(at->name + ": " + worst->check.name) + " (" +
                   worst->check.metric + " " +
                   (std::isfinite(worst->value) ? formatSignificant(worst->value, 4) : std::string("n/a")) +
                   ", full marks at <= " + formatSignificant(worst->fullBound, 4) + ").";
}

}  // namespace

bool slipsNeeded(const ExerciseResult& e) {
  // A slip is looked at where no listed mistake is named, or one only close to the frames is.
  if (e.outcome() != Outcome::Graded || e.diagnosis.empty() ||
      !(e.mistake.empty() || e.explanation.rfind("like:", 0) == 0))
    return false;
  for (auto& c : e.configurations)
    if (c.drawn && !c.slipsDrawn) return true;
  return false;
}

std::string quotedList(const std::vector<std::string>& names) { return englishList(names, "'"); }

void diagnose(const Exercise& ex, ExerciseResult& e) {
  diagnoseFromEvidence(ex, e);
  // Where no listed mistake is named, say what the explanation could look at: without a probe of
  // the function by itself, the frames are all there is.
  static const std::string kFramesAlone =
      "This exercise has no probe of its function by itself: the diagnosis above rests on the frames alone.";
  if (!e.diagnosis.empty() && e.mistake.empty() && e.outcome() == Outcome::Graded && ex.probes.empty() &&
      std::find(e.notes.begin(), e.notes.end(), kFramesAlone) == e.notes.end())
    e.notes.push_back(kFramesAlone);
}

}  // namespace shadelab
