// Files the window writes: screenshots (PNG + the JSON that reproduces them headless) and
// parameter presets. Everything goes under out/ (or $SHADELAB_OUT) with a fresh name, written
// to a temporary file and renamed: nothing the user has is ever overwritten.
#pragma once
#include <string>
#include <vector>

#include "app/host/lab_host.h"
#include "app/ui/status_line.h"

namespace shadelab {

// Each returns the Messages panel's line: what it wrote or loaded, or why it could not.
StatusLine saveScreenshot(LabHost& host, glm::ivec2 size);
StatusLine savePreset(LabHost& host);
StatusLine loadPreset(LabHost& host, const std::string& path);
std::vector<std::string> listPresets();
// The window's default framebuffer, UI included. Returns "" or an error.
std::string saveWindowImage(const std::string& path, glm::ivec2 size);
// The frame's preset beside a screenshot saved as `png` (its name with .json), as F12 writes one:
// what `shadelab render --preset` draws the lab's frame again from. A file already there is kept.
std::string saveScreenshotPreset(LabHost& host, const std::string& png);

}  // namespace shadelab
