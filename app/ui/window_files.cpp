#include "app/ui/window_files.h"

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "app/gl/gl.h"
#include "app/measure/report.h"
#include "app/ui/platform.h"
#include "app/util/output_files.h"

namespace fs = std::filesystem;

namespace shadelab {

namespace {

// The state that reproduces the lab's frame at `size`, and the command that does.
nlohmann::json framePreset(LabHost& host, glm::ivec2 size, const fs::path& json) {
  nlohmann::json state = host.stateJson();
  state["size"] = {size.x, size.y};
  state["reproduce"] = "shadelab render --preset " + json.string() + " --out again.png";  // the preset carries the size
  return state;
}

}  // namespace

std::string saveScreenshotPreset(LabHost& host, const std::string& png) {
  const fs::path json = fs::path(png).replace_extension(".json");
  std::error_code ec;
  if (fs::exists(json, ec)) return json.string() + " is there already: not overwritten";
  const glm::ivec2 size = host.target() ? host.target()->size() : glm::ivec2(1280, 720);
  return writeTextFile(json.string(), framePreset(host, size, json).dump(2) + "\n");
}

StatusLine saveScreenshot(LabHost& host, glm::ivec2 size) {
  const fs::path png = freshName("screenshots", std::string(host.lab().id()), ".png");
  if (auto err = writePng(png.string(), host.readImage()); !err.empty()) return StatusLine::failed(err);
  const nlohmann::json state = framePreset(host, size, fs::path(png).replace_extension(".json"));
  const std::string cmd = state["reproduce"];
  if (auto err = writeTextFile(fs::path(png).replace_extension(".json").string(), state.dump(2) + "\n"); !err.empty())
    return StatusLine::failed(err);
  offerDownload(png.string());
  offerDownload(fs::path(png).replace_extension(".json").string());
  return StatusLine::done("saved " + png.string() + " (+ .json; reproduce with: " + cmd + ")");
}

StatusLine savePreset(LabHost& host) {
  const fs::path p = freshName("presets", std::string(host.lab().id()), ".json");
  if (auto err = writeTextFile(p.string(), host.stateJson().dump(2) + "\n"); !err.empty())
    return StatusLine::failed(err);
  offerDownload(p.string());
  return StatusLine::done("saved preset " + p.string());
}

StatusLine loadPreset(LabHost& host, const std::string& path) {
  Preset preset;
  if (auto err = readPreset(path, preset); !err.empty()) return StatusLine::failed(err);
  if (auto err = host.applyPreset(preset); !err.empty()) return StatusLine::failed(path + ": " + err);
  return StatusLine::done("loaded " + path);
}

std::vector<std::string> listPresets() {
  std::vector<std::string> out;
  std::error_code ec;
  for (auto& e : fs::directory_iterator(outputDir("presets"), ec))
    if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string saveWindowImage(const std::string& path, glm::ivec2 size) {
  ImageF img;
  img.size = size;
  std::vector<unsigned char> rgba(size_t(size.x) * size.y * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  img.rgba.resize(rgba.size());
  for (int y = 0; y < size.y; ++y)
    for (size_t i = 0; i < size_t(size.x) * 4; ++i)
      img.rgba[size_t(y) * size.x * 4 + i] = rgba[size_t(size.y - 1 - y) * size.x * 4 + i] / 255.0f;
  return writePng(path, img);
}

}  // namespace shadelab
