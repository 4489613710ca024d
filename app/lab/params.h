// One list of parameters per lab, visited by everyone who needs it: the ImGui panel, the CLI
// (--set lab.key=value), JSON presets, `shadelab list` and the tutorial tables. A lab writes
// each field once, with range, units and help, in its visitParams().
#pragma once
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/util/format.h"

namespace shadelab {

struct ParamInfo {
  std::string_view key;    // CLI/JSON key within the lab, e.g. "shininess"
  std::string_view label;  // UI label, e.g. "Shininess"
  std::string_view units;  // "", "deg", "W", "px", ...
  std::string_view help;   // one or two sentences; tooltip, `list`, error messages
};

class ParamVisitor {
 public:
  virtual ~ParamVisitor() = default;
  virtual void floatParam(const ParamInfo& info, float& value, float min, float max, bool logScale = false) = 0;
  virtual void intParam(const ParamInfo& info, int& value, int min, int max) = 0;
  virtual void boolParam(const ParamInfo& info, bool& value) = 0;
  virtual void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) = 0;
  // A file the lab reads (a clean reference mesh): a path, "" for none, with the extensions it
  // may have (".obj"). Presets and --set carry it; a visitor that has no use for it ignores it.
  virtual void fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) {}
  // A heading over the parameters that follow ("Light", "Bias"): the panel folds the group, `list`
  // prints it. Parameters before the first section stand on their own.
  virtual void section(std::string_view title) {}
  // A button ("add noise", "bake"): `run` acts on the lab at once. The CLI runs it with
  // --do lab.key; it is no value, so presets and --set leave it alone.
  virtual void action(const ParamInfo& info, const std::function<void()>& run) {}
  // The next parameter can have no effect here (the driver lacks an extension): the panel greys
  // it out and shows `reason`, `list` says so. It still holds and accepts a value.
  virtual void unavailable(std::string_view reason) {}

  // Every parameter visited while the guard lives can have no effect here, for one reason ("":
  // they can): a group greyed out at once. The outermost group's reason is shown, then a
  // parameter's own unavailable() reason.
  //   { const ParamVisitor::UnavailableGroup cascadesOnly(v, p.fit != MapFit::Cascades ? "fit is not 'cascades'" : "");
  //     v.intParam(...); v.floatParam(...); }
  class UnavailableGroup {
   public:
    UnavailableGroup(ParamVisitor& v, std::string_view reason) : v_(v), outer_(v.groupReason_) {  // reason is copied
      if (outer_.empty()) v.groupReason_ = reason;
    }
    ~UnavailableGroup() { v_.groupReason_ = outer_; }
    UnavailableGroup(const UnavailableGroup&) = delete;
    UnavailableGroup& operator=(const UnavailableGroup&) = delete;

   private:
    ParamVisitor& v_;
    std::string outer_;
  };
  // Why the parameter being visited can have no effect: its group's reason, else `own` (what
  // unavailable() said for it), else "".
  std::string_view unavailableReason(std::string_view own) const { return groupReason_.empty() ? own : groupReason_; }

  // Enums are stored as enum classes in Params and visited as named choices.
  template <typename E>
  void enumParam(const ParamInfo& info, E& value, std::span<const std::string_view> names) {
    int i = static_cast<int>(value);
    choiceParam(info, i, names);
    value = static_cast<E>(i);
  }

 private:
  std::string groupReason_;  // owned: a reason built for the group outlives nothing it points into
};

// Sets one parameter from text ("0.25", "on", "phong"). Returns "" or a one-line error that
// names the key and what is valid.
class SetFromString final : public ParamVisitor {
 public:
  SetFromString(std::string_view labId, std::string_view key, std::string_view text)
      : labId_(labId), key_(key), text_(text) {}
  void floatParam(const ParamInfo& info, float& value, float min, float max, bool logScale) override;
  void intParam(const ParamInfo& info, int& value, int min, int max) override;
  void boolParam(const ParamInfo& info, bool& value) override;
  void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) override;
  void fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) override;
  void action(const ParamInfo& info, const std::function<void()>&) override;
  // Call after visiting: the error, including "unknown key" with the valid keys.
  std::string result() const;

 private:
  std::string fail(const ParamInfo& info, const std::string& valid);
  std::string labId_, key_, text_, error_;
  std::vector<std::string> keys_;
  bool found_ = false;
};

// Runs one action by key. result(): "" or an error naming the valid actions.
class RunAction final : public ParamVisitor {
 public:
  RunAction(std::string_view labId, std::string_view key) : labId_(labId), key_(key) {}
  void floatParam(const ParamInfo&, float&, float, float, bool) override {}
  void intParam(const ParamInfo&, int&, int, int) override {}
  void boolParam(const ParamInfo&, bool&) override {}
  void choiceParam(const ParamInfo&, int&, std::span<const std::string_view>) override {}
  void action(const ParamInfo& info, const std::function<void()>& run) override;
  std::string result() const;

 private:
  std::string labId_, key_;
  std::vector<std::string> actions_;
  bool ran_ = false;
};

// Writes every parameter as "key": value text pairs (value as SetFromString accepts it).
class CollectAsText final : public ParamVisitor {
 public:
  void floatParam(const ParamInfo& info, float& value, float, float, bool) override;
  void intParam(const ParamInfo& info, int& value, int, int) override;
  void boolParam(const ParamInfo& info, bool& value) override;
  void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) override;
  void fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view>) override;
  std::vector<std::pair<std::string, std::string>> values;
};

// One line per parameter for `shadelab list`: key, type, default/current, range, units, help.
class DescribeParams final : public ParamVisitor {
 public:
  explicit DescribeParams(std::string_view labId) : labId_(labId) {}
  void floatParam(const ParamInfo& info, float& value, float min, float max, bool) override;
  void intParam(const ParamInfo& info, int& value, int min, int max) override;
  void boolParam(const ParamInfo& info, bool& value) override;
  void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) override;
  void fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) override;
  void section(std::string_view title) override;
  void action(const ParamInfo& info, const std::function<void()>&) override;
  void unavailable(std::string_view reason) override { unavailable_ = reason; }
  std::vector<std::string> lines;

 private:
  void add(const ParamInfo& info, const std::string& type, const std::string& value);
  std::string labId_;
  std::string unavailable_;  // for the next parameter
};

}  // namespace shadelab
