#include "app/ui/xy_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {
namespace {

const ImU32 kPalette[] = {IM_COL32(230, 90, 80, 255),  IM_COL32(90, 160, 230, 255),  IM_COL32(110, 200, 110, 255),
                          IM_COL32(240, 170, 60, 255), IM_COL32(180, 130, 220, 255), IM_COL32(220, 220, 220, 255)};

std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

void drawXYPlot(const char* id, const XYPlot& plot, float height) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 120.0f);
  int namedSeries = 0;
  for (auto& s : plot.series) namedSeries += !s.name.empty();
  height += 15.0f * float(namedSeries);  // the legend goes below the axes
  ImGui::InvisibleButton(id, ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  int named = 0;
  for (auto& s : plot.series) named += !s.name.empty();
  const float legend = 15.0f * float(named);
  const float left = 46, bottom = 30 + legend, top = 6, right = 8;
  const ImVec2 p0(origin.x + left, origin.y + top), p1(origin.x + width - right, origin.y + height - bottom);
  dl->AddRectFilled(p0, p1, IM_COL32(25, 25, 28, 255));
  dl->AddRect(p0, p1, IM_COL32(120, 120, 120, 255));

  auto yOf = [&](float v) { return plot.logY ? std::log10(std::max(v, 1e-30f)) : v; };
  float x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (auto& s : plot.series)
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || (plot.logY && s.y[i] <= 0)) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, yOf(s.y[i]));
      y1 = std::max(y1, yOf(s.y[i]));
    }
  if (!std::isfinite(x0)) {
    dl->AddText(ImVec2(p0.x + 8, p0.y + 8), IM_COL32(150, 150, 150, 255), "no data yet");
    return;
  }
  if (!plot.logY && !plot.equalAxes) y0 = std::min(y0, 0.0f);
  if (x1 - x0 < 1e-12f) {
    x0 -= 0.5f;
    x1 += 0.5f;
  }
  if (y1 - y0 < 1e-12f) {
    y0 -= 0.5f;
    y1 += 0.5f;
  }
  const float padX = (x1 - x0) * 0.06f, padY = (y1 - y0) * 0.08f;
  x0 -= padX;
  x1 += padX;
  y1 += padY;
  if (plot.logY || plot.equalAxes) y0 -= padY;
  if (plot.equalAxes && !plot.logY) {
    // One unit the same length on both axes: widen whichever range is short for its side.
    const float perPixel = std::max((x1 - x0) / std::max(p1.x - p0.x, 1.0f), (y1 - y0) / std::max(p1.y - p0.y, 1.0f));
    const float cx = 0.5f * (x0 + x1), cy = 0.5f * (y0 + y1);
    x0 = cx - 0.5f * perPixel * (p1.x - p0.x);
    x1 = cx + 0.5f * perPixel * (p1.x - p0.x);
    y0 = cy - 0.5f * perPixel * (p1.y - p0.y);
    y1 = cy + 0.5f * perPixel * (p1.y - p0.y);
  }
  auto map = [&](float x, float y) {
    return ImVec2(p0.x + (x - x0) / (x1 - x0) * (p1.x - p0.x), p1.y - (yOf(y) - y0) / (y1 - y0) * (p1.y - p0.y));
  };
  // Axis labels: the ends of each range, and the names.
  const ImU32 grey = IM_COL32(170, 170, 170, 255);
  dl->AddText(ImVec2(p0.x, p1.y + 2), grey, shortNumber(x0).c_str());
  const std::string xHi = shortNumber(x1);
  dl->AddText(ImVec2(p1.x - ImGui::CalcTextSize(xHi.c_str()).x, p1.y + 2), grey, xHi.c_str());
  const std::string yHi = shortNumber(plot.logY ? std::pow(10.0, y1) : y1),
                    yLo = shortNumber(plot.logY ? std::pow(10.0, y0) : y0);
  dl->AddText(ImVec2(origin.x, p0.y), grey, yHi.c_str());
  dl->AddText(ImVec2(origin.x, p1.y - ImGui::GetFontSize()), grey, yLo.c_str());
  const std::string axes = plot.xLabel + "  (y: " + plot.yLabel + (plot.logY ? ", log" : "") + ")";
  dl->AddText(ImVec2(p0.x, p1.y + 2 + ImGui::GetFontSize()), grey, axes.c_str());

  for (float mx : plot.markX) {
    const float x = map(mx, 1.0f).x;
    for (float y = p0.y; y < p1.y; y += 8)
      dl->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 4, p1.y)), IM_COL32(240, 200, 60, 200));
  }
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  std::string tip;
  float bestDistance = 8.0f;
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const XYSeries& s = plot.series[k];
    const ImU32 color = s.color ? s.color : kPalette[k % 6];
    std::vector<ImVec2> pts;
    // A non-finite point ends one polyline and starts the next (several squares in one series).
    auto flush = [&] {
      if (!s.points && pts.size() >= 2) dl->AddPolyline(pts.data(), int(pts.size()), color, 0, 1.6f);
      if (!s.points) pts.clear();
    };
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
        flush();
      else if (!(plot.logY && s.y[i] <= 0)) {
        pts.push_back(map(s.x[i], s.y[i]));
        if (s.points) {
          const bool big = int(i) == s.highlight;
          dl->AddCircleFilled(pts.back(), big ? 5.5f : 3.5f, color);
          if (big) dl->AddCircle(pts.back(), 8.0f, IM_COL32(255, 255, 255, 220));
          const float d = std::hypot(mouse.x - pts.back().x, mouse.y - pts.back().y);
          if (hovered && d < bestDistance && i < s.tips.size()) {
            bestDistance = d;
            tip = s.tips[i];
          }
        }
      }
    flush();
    if (!s.name.empty()) {
      int row = 0;
      for (size_t j = 0; j < k; ++j) row += !plot.series[j].name.empty();
      const ImVec2 at(p0.x, p1.y + 6 + 2 * ImGui::GetFontSize() + 15.0f * float(row));
      dl->AddRectFilled(at, ImVec2(at.x + 8, at.y + 8), color);
      dl->AddText(ImVec2(at.x + 12, at.y - 4), grey, s.name.c_str());
    }
  }
  if (!tip.empty()) ImGui::SetTooltip("%s", tip.c_str());
}

}  // namespace shadelab
