// Window events of any kind (input, resizes, exposes, drops), counted: a window that has stopped
// drawing because nothing moved draws again when the count moves (window_app.cpp).
#pragma once

struct GLFWwindow;

namespace shadelab {

unsigned windowEvents();
void countWindowEvent(GLFWwindow*);
// Before Dear ImGui's backend is installed (it chains to them, so input still reaches ImGui).
void countInput(GLFWwindow* window);
// After it: resizes, exposes (a window uncovered must be drawn again) and iconifying.
void countWindowChanges(GLFWwindow* window);

}  // namespace shadelab
