// A small x/y plot on ImGui's draw list (1.86 has no plotting beyond PlotLines): lines for a
// lab's series (energy per iteration), points for measurements (error against cost).
#pragma once
#include <imgui.h>

#include <string>
#include <vector>

namespace shadelab {

struct XYSeries {
  std::string name;
  std::vector<float> x, y;
  ImU32 color = 0;                // 0: from the palette
  bool points = false;            // markers instead of a polyline
  std::vector<std::string> tips;  // per point, shown on hover (points only)
  int highlight = -1;             // a point drawn larger (the latest measurement)
};

struct XYPlot {
  std::string xLabel, yLabel;
  bool logY = false;
  std::vector<XYSeries> series;
  std::vector<float> markX;  // dashed vertical markers
  bool equalAxes = false;    // one unit as long on both axes (shapes in texel space)
};

// Draws into a box `height` pixels high across the available width.
void drawXYPlot(const char* id, const XYPlot& plot, float height);

}  // namespace shadelab
