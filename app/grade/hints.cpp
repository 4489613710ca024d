#include "app/grade/hints.h"

namespace shadelab {

namespace {

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

}  // namespace

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

}  // namespace shadelab
