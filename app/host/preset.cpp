#include "app/host/preset.h"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace fs = std::filesystem;

namespace shadelab {
namespace {

std::string optionalText(const nlohmann::json& state, const char* key, std::optional<std::string>& out) {
  if (!state.contains(key)) return {};
  if (!state[key].is_string()) return std::string("'") + key + "' must be a string";
  out = state[key].get<std::string>();
  return {};
}

}  // namespace

std::string parsePreset(const nlohmann::json& state, Preset& out) {
  out = Preset{};
  if (!state.is_object()) return "expected a JSON object with lab, scene, params, camera";
  if (auto err = optionalText(state, "lab", out.lab); !err.empty()) return err;
  if (auto err = optionalText(state, "scene", out.scene); !err.empty()) return err;
  if (auto err = optionalText(state, "camera", out.camera); !err.empty()) return err;
  if (auto err = optionalText(state, "height_map", out.heightMap); !err.empty()) return err;
  if (state.contains("params")) {
    const auto& params = state["params"];
    if (!params.is_object()) return "'params' must be an object of key: value";
    for (auto& [k, v] : params.items()) {
      if (v.is_object() || v.is_array() || v.is_null())
        return "params." + k + ": must be a number, a string or true/false";
      out.params.emplace_back(k, v.is_string() ? v.get<std::string>() : v.dump());
    }
  }
  if (state.contains("size")) {
    const auto& s = state["size"];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number())
      return "'size' must be [width, height] in pixels";
    auto clampPixels = [](double v) { return std::isfinite(v) ? int(std::clamp(v, 16.0, 16384.0)) : 16; };
    out.size = glm::ivec2(clampPixels(s[0].get<double>()), clampPixels(s[1].get<double>()));
  }
  if (state.contains("time")) {
    if (!state["time"].is_number()) return "'time' must be a number of seconds";
    const double t = state["time"].get<double>();
    if (!std::isfinite(t) || std::abs(t) > 1e6) return "'time' must be a number of seconds in [-1e6, 1e6]";
    out.time = float(t);
  }
  return {};
}

std::string readPreset(const fs::path& file, Preset& out) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return file.string() + ": cannot open preset (not a file)";
  if (fs::file_size(file, ec) > kMaxPresetBytes)
    return file.string() + ": too large for a preset (at most " + std::to_string(kMaxPresetBytes >> 10) + " KiB)";
  std::ifstream in(file, std::ios::binary);
  if (!in) return file.string() + ": cannot open preset";
  const nlohmann::json state = nlohmann::json::parse(in, nullptr, false);
  if (state.is_discarded()) return file.string() + ": not valid JSON; nothing changed";
  if (auto err = parsePreset(state, out); !err.empty()) return file.string() + ": " + err;
  return {};
}

}  // namespace shadelab
