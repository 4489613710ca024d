// The Measure panel: the current configuration's error against its ground truth beside its cost,
// and every configuration measured this session as a point of error against cost, with the
// Pareto front: the picture a student builds by dragging sliders.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/measure/report.h"
#include "app/ui/panels.h"
#include "app/ui/xy_plot.h"

namespace shadelab {

void drawMeasurePanel(LabHost& host, Measurer& measurer, MeasureUi& ui, const MeasureRequest& now,
                      StatusLine& message) {
  const ReferenceSpec spec = referenceOf(host.lab());
  if (spec.kind == TruthKind::None) {
    ImGui::TextDisabled("This configuration has no ground truth to measure against.");
    if (!spec.description.empty()) ImGui::TextWrapped("%s.", spec.description.c_str());
    return;
  }
  ImGui::TextWrapped("Truth: %s.", spec.description.c_str());
  const bool busy = measurer.busy();
  if (ImGui::Button(busy ? "Measuring..." : "Measure")) ui.requested = true;
  ImGui::SameLine();
  ImGui::BeginDisabled(!spec.cheap);
  bool autoMeasure = ui.autoMeasure && spec.cheap;
  if (ImGui::Checkbox("Auto", &autoMeasure)) ui.autoMeasure = autoMeasure;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(spec.cheap ? "Measure again whenever a setting or the view changes."
                                 : "This truth is expensive (traced, or many frames): press Measure.");
  ImGui::SameLine();
  if (ImGui::Button("Clear")) measurer.clear();

  // Start a measurement: asked for, or automatic once the configuration has been still a moment.
  const bool wantAuto = ui.autoMeasure && spec.cheap && now.signature != ui.measuredSignature && now.stillSeconds > 0.3;
  if ((ui.requested || wantAuto) && now.costs.size() > 0) {
    if (auto err = measurer.start(now.size, now.time, now.costs); !err.empty()) message = StatusLine::failed(err);
    ui.measuredSignature = now.signature;
    ui.requested = false;
  }

  const auto& history = measurer.history();
  if (history.empty()) {
    ImGui::TextDisabled("Press Measure to compare this frame with the truth.");
    return;
  }
  const Measurement& last = history.back();
  const bool current = ui.measuredSignature == now.signature && !busy;
  ImGui::TextColored(current ? ImVec4(0.6f, 1.0f, 0.6f, 1.0f) : ImVec4(0.8f, 0.8f, 0.5f, 1.0f), "%s",
                     current ? "Measured: these settings" : "Measured: earlier settings (press Measure)");
  ImGui::TextWrapped("%s; truth: %s", last.label.c_str(), last.truth.c_str());
  if (ImGui::BeginTable("metrics", 2, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    for (auto& [k, v] : last.values) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.5g", v);
    }
    ImGui::EndTable();
  }

  const auto plots = host.lab().judge()->plots();  // a truth implies a Judge
  if (plots.empty()) return;
  ui.plot = std::clamp(ui.plot, 0, int(plots.size()) - 1);
  if (plots.size() > 1) {
    std::string names;
    for (auto& p : plots) names += p.error + " / " + p.cost + '\0';
    ImGui::Combo("plot", &ui.plot, names.c_str());
  }
  const PlotSpec& p = plots[size_t(ui.plot)];
  // One series per truth, and the Pareto front of each: configurations judged against different
  // truths are never compared.
  SweepReport asReport;
  asReport.plots = {p};
  for (auto& m : history) {
    SweepRow row;
    row.label = m.label;
    row.truth = m.truth;
    row.values = m.values;
    asReport.rows.push_back(std::move(row));
  }
  XYPlot plot{p.cost, p.error, false, {}, {}};
  for (auto& truth : truthsOf(asReport)) {
    XYSeries points{truth, {}, {}, 0, true, {}, -1};
    XYSeries front{"", {}, {}, IM_COL32(200, 200, 200, 160), false, {}, -1};
    for (size_t i = 0; i < history.size(); ++i) {
      if (history[i].truth != truth) continue;
      if (i + 1 == history.size()) points.highlight = int(points.x.size());
      points.x.push_back(float(history[i].value(p.cost)));
      points.y.push_back(float(history[i].value(p.error)));
      char tip[512];
      std::snprintf(tip, sizeof tip, "%s\n%s %.4g, %s %.4g", history[i].label.c_str(), p.error.c_str(),
                    history[i].value(p.error), p.cost.c_str(), history[i].value(p.cost));
      points.tips.push_back(tip);
    }
    for (size_t i : paretoFront(asReport, p, truth)) {
      front.x.push_back(float(asReport.rows[i].value(p.cost)));
      front.y.push_back(float(asReport.rows[i].value(p.error)));
    }
    plot.series.push_back(std::move(front));
    plot.series.push_back(std::move(points));
  }
  drawXYPlot("measurements", plot, 190.0f);
  ImGui::TextDisabled("%zu configurations measured; grey line: the Pareto front. Hover a point.", history.size());
}

}  // namespace shadelab
