// Dear ImGui panels of the window front end. Each draws one concern and changes state only
// through the host (the same write path as the CLI and presets).
#pragma once
#include <deque>
#include <string>

#include "host/lab_host.h"

namespace shadelab {

// Widgets for a lab's parameter list; returns true when any value changed.
bool drawParamWidgets(Lab& lab);

struct FrameHistory {
  std::deque<float> frameMs;  // wall time between frames
  std::deque<float> gpuMs;    // summed pass time
  void push(float frame, float gpu);
};
void drawStatsPanel(const LabHost& host, const FrameHistory& history, double uiMs);

// Active programs with their status; a failed build shows file:line:col, the source line and a
// caret under the column. `status` receives messages such as "reloaded 2 programs".
void drawShaderPanel(LabHost& host, std::string& status);

void drawWarnings(const LabHost& host, const std::string& lastError);

}  // namespace shadelab
