// Files the window writes: screenshots (PNG + the JSON that reproduces them headless) and
// parameter presets. Everything goes under out/ (or $SHADELAB_OUT) with a fresh name, written
// to a temporary file and renamed: nothing the user has is ever overwritten.
#pragma once
#include <string>
#include <vector>

#include "app/host/lab_host.h"

namespace shadelab {

std::string saveScreenshot(LabHost& host, glm::ivec2 size);  // returns the message for the UI
std::string savePreset(LabHost& host);
std::string loadPreset(LabHost& host, const std::string& path);  // "" on success... or a message
std::vector<std::string> listPresets();
// The window's default framebuffer, UI included. Returns "" or an error.
std::string saveWindowImage(const std::string& path, glm::ivec2 size);

}  // namespace shadelab
