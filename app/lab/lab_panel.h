// Lab-specific views beside the parameters: a mesh-statistics table, an energy-per-iteration
// plot, a mip chain. A lab describes them as data and never calls ImGui: the window draws them
// (app/ui/lab_panels.cpp), and `shadelab render` writes their tables into its JSON, so the
// headless path reports the same numbers the student reads.
#pragma once
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

namespace gl {
class Texture2D;
}

namespace shadelab {

struct PanelText {
  std::string text;
};

struct PanelTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

struct PanelSeries {
  std::string name;
  std::vector<float> x, y;  // a non-finite point breaks the line (several outlines in one series)
};

struct PanelPlot {
  std::string title, xLabel, yLabel;
  bool logY = false;  // energies and errors that span decades
  std::vector<PanelSeries> series;
  std::vector<float> markX;  // vertical markers (the iteration where the energy grew)
  bool equalAxes = false;    // one unit as long on x as on y: shapes (a footprint in texel space)
};

struct PanelImage {
  const gl::Texture2D* texture = nullptr;  // owned by the lab; valid until its next update()
  glm::ivec2 size{0};                      // in pixels as drawn
  std::string caption;
};

using PanelItem = std::variant<PanelText, PanelTable, PanelPlot, PanelImage>;

struct LabPanel {
  std::string title;
  std::vector<PanelItem> items;
};

}  // namespace shadelab
