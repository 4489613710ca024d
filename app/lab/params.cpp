#include "app/lab/params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace shadelab {

static std::string joined(std::span<const std::string_view> names) {
  std::string s;
  for (auto n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

std::string SetFromString::fail(const ParamInfo& info, const std::string& valid) {
  error_ = labId_ + "." + std::string(info.key) + ": invalid value '" + text_ + "' (valid: " + valid + ")";
  return error_;
}

void SetFromString::floatParam(const ParamInfo& info, float& value, float min, float max, bool) {
  keys_.emplace_back(info.key);
  if (info.key != key_) return;
  found_ = true;
  char* end = nullptr;
  const double v = std::strtod(text_.c_str(), &end);
  // Compare as float: "0.1" must pass a range whose bound is the float 0.1f.
  if (text_.empty() || *end != '\0' || !std::isfinite(v) || float(v) < min || float(v) > max)
    fail(info, "a number in [" + formatNumber(min) + ", " + formatNumber(max) + "]" +
                   (info.units.empty() ? "" : " " + std::string(info.units)));
  else
    value = float(v);
}

void SetFromString::intParam(const ParamInfo& info, int& value, int min, int max) {
  keys_.emplace_back(info.key);
  if (info.key != key_) return;
  found_ = true;
  int v = 0;
  auto [ptr, ec] = std::from_chars(text_.data(), text_.data() + text_.size(), v);
  if (ec != std::errc() || ptr != text_.data() + text_.size() || v < min || v > max)
    fail(info, "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  else
    value = v;
}

void SetFromString::boolParam(const ParamInfo& info, bool& value) {
  keys_.emplace_back(info.key);
  if (info.key != key_) return;
  found_ = true;
  if (text_ == "1" || text_ == "true" || text_ == "on")
    value = true;
  else if (text_ == "0" || text_ == "false" || text_ == "off")
    value = false;
  else
    fail(info, "on, off, true, false, 1, 0");
}

void SetFromString::choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) {
  keys_.emplace_back(info.key);
  if (info.key != key_) return;
  found_ = true;
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == text_) {
      index = int(i);
      return;
    }
  fail(info, joined(names));
}

void SetFromString::fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) {
  keys_.emplace_back(info.key);
  if (info.key != key_) return;
  found_ = true;
  const std::string valid = "a " + joined(extensions) + " file, or '' for none";
  if (text_.empty()) {
    path.clear();
    return;
  }
  const std::filesystem::path file(text_);
  const std::string ext = file.extension().string();
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
    fail(info, valid);
    return;
  }
  // The error_code forms: a name longer than the file system allows is an answer, not a throw.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    error_ = labId_ + "." + std::string(info.key) + ": no such file '" + text_ + "' (valid: " + valid + ")";
    return;
  }
  path = text_;
}

void SetFromString::action(const ParamInfo& info, const std::function<void()>&) {
  if (info.key != key_) return;
  found_ = true;
  error_ = labId_ + "." + std::string(info.key) + " is an action, not a value: run it with --do " + labId_ + "." +
           std::string(info.key);
}

void RunAction::action(const ParamInfo& info, const std::function<void()>& run) {
  actions_.emplace_back(info.key);
  if (info.key != key_ || ran_) return;
  ran_ = true;
  run();
}

std::string RunAction::result() const {
  if (ran_) return {};
  std::string valid;
  for (auto& a : actions_) valid += (valid.empty() ? "" : ", ") + labId_ + "." + a;
  return "unknown action '" + labId_ + "." + key_ + "' (valid: " + (valid.empty() ? "this lab has none" : valid) + ")";
}

std::string SetFromString::result() const {
  if (found_) return error_;
  std::string valid;
  for (auto& k : keys_) valid += (valid.empty() ? "" : ", ") + labId_ + "." + k;
  return "unknown parameter '" + labId_ + "." + key_ + "' (valid: " + valid + ")";
}

void CollectAsText::floatParam(const ParamInfo& info, float& value, float, float, bool) {
  values.emplace_back(info.key, formatNumber(value));
}
void CollectAsText::intParam(const ParamInfo& info, int& value, int, int) {
  values.emplace_back(info.key, std::to_string(value));
}
void CollectAsText::boolParam(const ParamInfo& info, bool& value) {
  values.emplace_back(info.key, value ? "on" : "off");
}
void CollectAsText::fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view>) {
  values.emplace_back(info.key, path);
}
void CollectAsText::choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) {
  values.emplace_back(info.key, std::string(names[size_t(index)]));
}

void DescribeParams::add(const ParamInfo& info, const std::string& type, const std::string& value) {
  std::string line = "  " + labId_ + "." + std::string(info.key) + " = " + value + "  " + type;
  if (!info.units.empty()) line += " " + std::string(info.units);
  line += "\n      " + std::string(info.help);
  if (const std::string_view why = unavailableReason(unavailable_); !why.empty())
    line += "\n      (unavailable: " + std::string(why) + ")";
  unavailable_.clear();
  lines.push_back(line);
}
void DescribeParams::floatParam(const ParamInfo& info, float& value, float min, float max, bool) {
  add(info, "float [" + formatNumber(min) + ", " + formatNumber(max) + "]", formatNumber(value));
}
void DescribeParams::intParam(const ParamInfo& info, int& value, int min, int max) {
  add(info, "int [" + std::to_string(min) + ", " + std::to_string(max) + "]", std::to_string(value));
}
void DescribeParams::boolParam(const ParamInfo& info, bool& value) { add(info, "on|off", value ? "on" : "off"); }
void DescribeParams::section(std::string_view title) { lines.push_back("  [" + std::string(title) + "]"); }
void DescribeParams::action(const ParamInfo& info, const std::function<void()>&) {
  lines.push_back("  " + labId_ + "." + std::string(info.key) + "  action (--do " + labId_ + "." +
                  std::string(info.key) + ")\n      " + std::string(info.help));
}
void DescribeParams::fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) {
  add(info, "file (" + joined(extensions) + ", or '' for none)", path.empty() ? "''" : path);
}
void DescribeParams::choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) {
  add(info, "one of " + joined(names), std::string(names[size_t(index)]));
}

}  // namespace shadelab
