// Presets: what the app saves beside every screenshot and in out/presets/ (lab, scene, a height
// map given for it, params, camera, and for screenshots the size and time), and what `render --preset` and a .json
// dropped on the window apply. Presets travel between people, so they are untrusted: the file is read only if it is a
// regular file of modest size, and every field is checked for type and range here, before anything is applied.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

namespace shadelab {

struct Preset {
  std::optional<std::string> lab, scene, camera;
  std::optional<std::string> heightMap;  // an image file: the scene's height map (LabHost::setHeightMap)
  std::vector<std::pair<std::string, std::string>> params;  // key -> value as text, in file order
  std::optional<glm::ivec2> size;                           // clamped to [16, 16384]
  std::optional<float> time;                                // seconds, finite
};

inline constexpr std::uintmax_t kMaxPresetBytes = 1 << 20;

// "" on success, else one line naming the key and what it must be.
std::string parsePreset(const nlohmann::json& state, Preset& out);
// Reads and parses `file`; errors start with the file's name.
std::string readPreset(const std::filesystem::path& file, Preset& out);

}  // namespace shadelab
