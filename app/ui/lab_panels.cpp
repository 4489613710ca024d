// The lab's own panels (app/lab/lab_panel.h), drawn as ImGui widgets, and the jobs overlay.
#include <imgui.h>

#include "app/gl/texture.h"
#include "app/ui/panels.h"
#include "app/ui/xy_plot.h"

namespace shadelab {
namespace {

struct DrawItem {
  int index;
  void operator()(const PanelText& t) const { ImGui::TextWrapped("%s", t.text.c_str()); }
  void operator()(const PanelTable& t) const {
    if (t.columns.empty()) return;
    const std::string id = "table" + std::to_string(index);
    if (!ImGui::BeginTable(id.c_str(), int(t.columns.size()), ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) return;
    for (auto& c : t.columns) ImGui::TableSetupColumn(c.c_str());
    ImGui::TableHeadersRow();
    for (auto& row : t.rows) {
      ImGui::TableNextRow();
      for (auto& cell : row) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(cell.c_str());
      }
    }
    ImGui::EndTable();
  }
  void operator()(const PanelPlot& p) const {
    if (!p.title.empty()) ImGui::TextUnformatted(p.title.c_str());
    XYPlot plot{p.xLabel, p.yLabel, p.logY, {}, p.markX, p.equalAxes};
    for (auto& s : p.series) {
      XYSeries& line = plot.series.emplace_back();
      line.name = s.name;
      line.x = s.x;
      line.y = s.y;
    }
    drawXYPlot(("plot" + std::to_string(index)).c_str(), plot, p.equalAxes ? 220.0f : 150.0f);
  }
  void operator()(const PanelImage& img) const {
    if (!img.texture) return;
    ImGui::Image(reinterpret_cast<ImTextureID>(intptr_t(img.texture->id())),
                 ImVec2(float(img.size.x), float(img.size.y)), ImVec2(0, 1), ImVec2(1, 0));
    if (!img.caption.empty()) ImGui::TextDisabled("%s", img.caption.c_str());
  }
};

}  // namespace

void drawLabPanels(const Lab& lab) {
  int index = 0;
  for (auto& panel : lab.panels()) {
    if (!ImGui::CollapsingHeader(panel.title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
    ImGui::PushID(panel.title.c_str());
    for (auto& item : panel.items) std::visit(DrawItem{index++}, item);
    ImGui::PopID();
  }
}

bool drawJobs(JobRunner& jobs) {
  const auto running = jobs.status();
  for (auto& j : running) {
    ImGui::PushID(j.key.c_str());
    char overlay[256];
    std::snprintf(overlay, sizeof overlay, "%s%s %3.0f%% %s", j.cancelling ? "cancelling: " : "", j.label.c_str(),
                  j.progress * 100.0f, j.stage.c_str());
    ImGui::ProgressBar(j.progress, ImVec2(ImGui::GetContentRegionAvail().x - 70.0f, 0.0f), overlay);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) jobs.cancel(j.key);
    ImGui::PopID();
  }
  return !running.empty();
}

}  // namespace shadelab
