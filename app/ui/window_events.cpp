#include "app/ui/window_events.h"

#include <GLFW/glfw3.h>

namespace shadelab {

namespace {
unsigned events = 0;  // GLFW calls back on the thread that polls: the window's
}

unsigned windowEvents() { return events; }

void countWindowEvent(GLFWwindow*) { ++events; }

void countInput(GLFWwindow* w) {
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double, double) { countWindowEvent(win); });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int, int, int) { countWindowEvent(win); });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double) { countWindowEvent(win); });
  glfwSetCharCallback(w, [](GLFWwindow* win, unsigned) { countWindowEvent(win); });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int) { countWindowEvent(win); });
  glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int) { countWindowEvent(win); });
}

void countWindowChanges(GLFWwindow* w) {
  glfwSetFramebufferSizeCallback(w, [](GLFWwindow* win, int, int) { countWindowEvent(win); });
  glfwSetWindowRefreshCallback(w, countWindowEvent);
  glfwSetWindowIconifyCallback(w, [](GLFWwindow* win, int) { countWindowEvent(win); });
}

}  // namespace shadelab
