#include "app/ui/platform.h"

#include <GLFW/glfw3.h>

#include <algorithm>

namespace shadelab {

void runMainLoop(std::function<bool()> frame) {
  while (frame()) {
  }
}

void offerDownload(const std::string&) {}

std::string copyLink(const std::string& fragment) {
  const std::string link = "index.html#" + fragment;
  glfwSetClipboardString(nullptr, link.c_str());
  return link;
}

void persistStudentFiles() {}

void showExerciseText(const std::string&, const std::string&, const std::string&) {}

std::vector<OpenedCourse> takeOpenedCourses() { return {}; }

const char* missingDataAdvice() { return "Run tools/get_data.sh to fetch them."; }

void waitForEvents(double seconds) { glfwWaitEventsTimeout(seconds); }

ShlGetProcAddress glProcLoader() { return reinterpret_cast<ShlGetProcAddress>(glfwGetProcAddress); }

void enableContextFeatures() {}

void followPageSize(GLFWwindow*) {}

const char* imguiGlslVersion() { return "#version 330 core"; }

float contentScale(GLFWwindow* window) {
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window, &sx, &sy);
  return std::max(sx, sy);
}

}  // namespace shadelab
