#include <imgui.h>

#include <algorithm>
#include <vector>

#include "app/ui/panels.h"

namespace shadelab {

void FrameHistory::push(float frame, float gpu) {
  frameMs.push_back(frame);
  gpuMs.push_back(gpu);
  while (frameMs.size() > 240) frameMs.pop_front();
  while (gpuMs.size() > 240) gpuMs.pop_front();
}

void drawStatsPanel(const LabHost& host, const FrameHistory& history, double uiMs) {
  const auto& passes = host.lastPasses();
  double gpu = 0, cpu = 0;
  for (auto& p : passes) {
    gpu += p.gpuMs;
    cpu += p.cpuMs;
  }
  ImGui::Text("Passes that ran this frame: %d", int(passes.size()));
  if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 4.5f);
    ImGui::TableSetupColumn("CPU ms", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 4.5f);
    ImGui::TableHeadersRow();
    for (auto& p : passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", p.name.c_str());  // "shadow map: key point 2048^2 D24 x6 (1 pass)" is long
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", p.gpuMs);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", p.cpuMs);
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", gpu);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", cpu);
    ImGui::EndTable();
  }
  ImGui::Text("timer: %s", host.timerClock());
  ImGui::Text("UI %.2f ms", uiMs);
  // Material textures the host uploaded for the scene; a lab that builds its own (the filtering lab's mip
  // chain) shows them in its panels.
  ImGui::TextWrapped("scene: %zu triangles, %d material textures uploaded, built %d times",
                     host.scene().triangleCount(), host.gpuScene().texturesUploaded(), host.sceneBuilds());
  std::vector<float> frame(history.frameMs.begin(), history.frameMs.end()),
      g(history.gpuMs.begin(), history.gpuMs.end());
  if (frame.size() >= 2) {
    const ImVec2 plotSize(ImGui::GetContentRegionAvail().x, 50);  // 1.86 takes no negative widths here
    const float top = *std::max_element(frame.begin(), frame.end()) * 1.1f;
    const std::string fl = "frame " + std::to_string(int(frame.back() + 0.5f)) + " ms";
    ImGui::PlotLines("##frame", frame.data(), int(frame.size()), 0, fl.c_str(), 0.0f, top, plotSize);
    const std::string gl = "GPU " + std::to_string(int(g.back() + 0.5f)) + " ms";
    ImGui::PlotLines("##gpu", g.data(), int(g.size()), 0, gl.c_str(), 0.0f, top, plotSize);
  }
}

void drawShaderPanel(LabHost& host, StatusLine& status) {
  auto& lib = host.shaders();
  ImGui::TextUnformatted("Search path (first match wins):");
  for (auto& root : lib.searchPath().roots()) ImGui::BulletText("%s", root.string().c_str());
  for (auto& [rel, file] : lib.searchPath().overrides())
    ImGui::BulletText("%s -> %s (dropped)", rel.c_str(), file.string().c_str());
  if (ImGui::Button("Rebuild all")) {
    int failed = 0;
    for (auto& p : host.lab().activePrograms()) failed += !lib.rebuild(*p, true);
    status = failed ? StatusLine::failed(std::to_string(failed) + " program(s) failed to build")
                    : StatusLine::done("rebuilt");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("Edit a file and save: it reloads. Drop a .vert/.frag/.geom/.glsl on the window to override it.");
  std::vector<std::string> shown;  // an error in a shared include is listed once, under its first program
  for (auto& p : host.lab().activePrograms()) {
    const bool failed = p->lastBuildFailed();
    ImGui::PushStyleColor(ImGuiCol_Text, failed ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(0.5f, 1, 0.5f, 1));
    ImGui::Text("%s %s (build %d)%s", failed ? "[error]" : "[ok]", p->spec().name.c_str(), p->generation(),
                !p->hasGoodProgram() ? " - never compiled: drawing the fallback"
                : failed             ? " - showing last good"
                                     : "");
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) {
      std::string files;
      for (auto& f : p->files()) files += f.string() + "\n";
      ImGui::SetTooltip("%s", files.c_str());
    }
    // What a student's version of this program can read: every uniform the lab sets on it.
    if (const auto& names = p->uniformsSet();
        !names.empty() && ImGui::TreeNode(p.get(), "uniforms the lab sets (%zu)", names.size())) {
      std::string list;
      for (auto& n : names) list += (list.empty() ? "" : ", ") + n;
      ImGui::TextWrapped("%s", list.c_str());
      ImGui::TreePop();
    }
    if (!failed) continue;
    for (auto& d : p->diagnostics()) {
      const std::string text = d.format();
      if (std::find(shown.begin(), shown.end(), text) != shown.end()) {
        ImGui::TextDisabled("    the same error as above (%s)", d.file.empty() ? "link" : d.file.c_str());
        continue;
      }
      shown.push_back(text);
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.4f, 1));
      ImGui::TextWrapped("%s", d.format().c_str());
      ImGui::PopStyleColor();
      if (!d.sourceLine.empty()) {
        ImGui::TextUnformatted(("    " + d.sourceLine).c_str());
        if (d.column > 0)
          ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "    %s^", std::string(size_t(d.column - 1), ' ').c_str());
      } else if (d.line == 0 && d.raw != d.message && !d.raw.empty()) {
        ImGui::TextDisabled("    %s", d.raw.c_str());
      }
    }
  }
}

void drawWarnings(const LabHost& host, const StatusLine& last) {
  if (last.problem) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.45f, 1));
    ImGui::TextWrapped("%s", last.text.c_str());
    ImGui::PopStyleColor();
  } else if (!last.empty()) {
    ImGui::TextWrapped("%s", last.text.c_str());
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.8f, 0.3f, 1));
  for (auto& w : host.warnings()) ImGui::TextWrapped("! %s", w.c_str());
  ImGui::PopStyleColor();
}

}  // namespace shadelab
