#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "app/ui/panels.h"

namespace shadelab {
namespace {

class ImGuiParams final : public ParamVisitor {
 public:
  bool changed = false;
  std::string fileUnderMouse;

  void floatParam(const ParamInfo& info, float& value, float min, float max, bool logScale) override {
    if (!open_) return;
    Greyed greyed(*this, unavailable_);
    const std::string label = withUnits(info);
    changed |= ImGui::SliderFloat(label.c_str(), &value, min, max, logScale ? "%.4g" : "%.3f",
                                  logScale ? ImGuiSliderFlags_Logarithmic : 0);
    value = std::clamp(value, min, max);  // ctrl+click typing may leave the range
    tooltip(info);
  }
  void intParam(const ParamInfo& info, int& value, int min, int max) override {
    if (!open_) return;
    Greyed greyed(*this, unavailable_);
    const std::string label = withUnits(info);
    changed |= ImGui::SliderInt(label.c_str(), &value, min, max);
    value = std::clamp(value, min, max);
    tooltip(info);
  }
  void boolParam(const ParamInfo& info, bool& value) override {
    if (!open_) return;
    Greyed greyed(*this, unavailable_);
    changed |= ImGui::Checkbox(std::string(info.label).c_str(), &value);
    tooltip(info);
  }
  void choiceParam(const ParamInfo& info, int& index, std::span<const std::string_view> names) override {
    if (!open_) return;
    Greyed greyed(*this, unavailable_);
    const std::string label(info.label);
    if (ImGui::BeginCombo(label.c_str(), std::string(names[size_t(index)]).c_str())) {
      for (size_t i = 0; i < names.size(); ++i)
        if (ImGui::Selectable(std::string(names[i]).c_str(), int(i) == index)) {
          changed |= int(i) != index;
          index = int(i);
        }
      ImGui::EndCombo();
    }
    tooltip(info);
  }
  // The file's name (the whole path on hover), a drop target for another, and Clear.
  void fileParam(const ParamInfo& info, std::string& path, std::span<const std::string_view> extensions) override {
    if (!open_) return;
    Greyed greyed(*this, unavailable_);
    std::string kinds;
    for (auto e : extensions) kinds += (kinds.empty() ? "" : "/") + std::string(e);
    const std::string shown =
        path.empty() ? "none: drop a " + kinds + " file here" : std::filesystem::path(path).filename().string();
    ImGui::BeginGroup();
    ImGui::TextUnformatted(std::string(info.label).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", shown.c_str());
    if (!path.empty()) {
      ImGui::SameLine();
      if (ImGui::SmallButton(("Clear##" + std::string(info.key)).c_str())) {
        path.clear();
        changed = true;
      }
    }
    ImGui::EndGroup();
    if (ImGui::IsItemHovered()) fileUnderMouse = info.key;
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
      if (!path.empty()) ImGui::TextUnformatted(path.c_str());
      ImGui::TextUnformatted(std::string(info.help).c_str());
      ImGui::TextDisabled("drop a %s file on this line, or --set %s=FILE", kinds.c_str(),
                          std::string(info.key).c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
  // A folding header per section; its parameters are laid out only while it is open.
  void section(std::string_view title) override {
    open_ = ImGui::CollapsingHeader(std::string(title).c_str(), ImGuiTreeNodeFlags_DefaultOpen);
    unavailable_.clear();  // said for a parameter of a folded section, which drew nothing
  }
  void unavailable(std::string_view reason) override { unavailable_ = reason; }
  void action(const ParamInfo& info, const std::function<void()>& run) override {
    if (!open_) return;
    if (ImGui::Button(std::string(info.label).c_str())) {
      run();
      changed = true;
    }
    tooltip(info, "--do ");
  }

 private:
  // Greys out one widget that can have no effect here, and says why beside it.
  class Greyed {
   public:
    // `own`: the widget's own reason, used up here; a group's reason comes first.
    Greyed(const ParamVisitor& v, std::string& own) : reason_(v.unavailableReason(own)) {
      own.clear();
      if (!reason_.empty()) ImGui::BeginDisabled();
    }
    ~Greyed() {
      if (reason_.empty()) return;
      ImGui::EndDisabled();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("%s", reason_.c_str());
      ImGui::PopTextWrapPos();
    }

   private:
    std::string reason_;
  };

  bool open_ = true;
  std::string unavailable_;  // for the next widget
  static std::string withUnits(const ParamInfo& info) {
    return info.units.empty() ? std::string(info.label)
                              : std::string(info.label) + " (" + std::string(info.units) + ")";
  }
  static void tooltip(const ParamInfo& info, const char* flag = "--set ") {
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
      ImGui::TextUnformatted(std::string(info.help).c_str());
      ImGui::TextDisabled("%s%s", flag, std::string(info.key).c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
};

}  // namespace

bool drawParamWidgets(Lab& lab, std::string* fileUnderMouse) {
  ImGuiParams v;
  ImGui::PushItemWidth(-175);
  lab.visitParams(v);
  ImGui::PopItemWidth();
  if (fileUnderMouse) *fileUnderMouse = v.fileUnderMouse;
  return v.changed;
}

}  // namespace shadelab
