// The Exercises section of the window (and of the page): every exercise with its statement, a
// button that puts the starter into the student's folder and opens it in the editor, and Check,
// which runs the exercise's rubric in place (grade/exercise_check.h) and shows the grader's lines:
// one per check, PASS / PARTIAL / FAIL, the hint under each that lost points, and the total.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "app/gl/texture.h"
#include "app/grade/exercise_check.h"
#include "app/grade/pixel_trace.h"
#include "app/grade/progress.h"
#include "app/ui/status_line.h"

namespace shadelab {

class LabHost;
struct ShaderEditor;

struct ExercisePanel {
  std::vector<std::string> ids;      // every exercise, read once, grouped by lab, then level
  std::vector<std::string> headers;  // "shadows: from scratch" above the first of each group, else ""
  bool listed = false;
  std::string selected;                     // the exercise shown ("" = none)
  std::string statement;                    // its statement.md
  std::vector<std::string> configurations;  // its rubric's configurations a student sees (hidden ones left out)
  std::vector<std::string> files;           // the files the student writes
  int shown = -1;                           // the one in the viewport, or -1
  bool showStatement = false;
  bool checkRequested = false;  // --check / the link's "check": press Check on the next frame
  bool reveal = false;          // a Check started: the panel scrolls to its results until it ends
  ExerciseCheck check;
  // The last Check's pictures as textures, per configuration that lost points: the student's frame,
  // the solution's, the difference; and where each one's wipe between the first two stands.
  std::vector<std::array<gl::Texture2D, 3>> pictures;
  std::vector<float> wipes;
  int picturesOf = -1;  // the check's generation they were made from
  // The inspector (grade/pixel_trace.h): the exercised function traced at a pixel of the
  // configuration on screen, asked for with I over the viewport (requestInspection) and traced
  // between frames, in the grader's frame at the same point of the view.
  bool inspectRequested = false;
  glm::ivec2 inspectPixel{0}, inspectViewport{1};  // the viewport's pixel and the viewport's size then
  glm::mat4 inspectedView{0.0f};                   // the camera then: the mark stays while it does
  std::vector<InspectionRow> inspection;           // the table, as `shadelab inspect` prints it
  PixelInspection inspected;
  size_t inspectedConfiguration = 0;  // the rubric's index
  // A row of the table clicked: that variable over the whole frame, yours, the solution's and
  // their difference (grade/pixel_trace.h: drawVariable), drawn between frames.
  bool pictureRequested = false;
  std::string pictureName;
  int pictureLine = 0;
  gl::Texture2D picture;
  std::string pictureSays;
  // The student's progress (grade/progress.h), read from their folder once it is known.
  Progress progress;
  std::filesystem::path progressFolder;

  void select(const std::string& id);
};

// Opens exercise `id` where it is done: selected in the section, its lab on screen with the first
// configuration's scene, settings and camera. Returns the Messages panel's line.
StatusLine openExercise(ExercisePanel& panel, LabHost& host, const std::string& id);
// Puts configuration `index` of the selected exercise in the viewport, as the grader draws it (the
// lab's defaults, then the configuration's scene, settings and camera); the student's files draw it.
StatusLine showConfiguration(ExercisePanel& panel, LabHost& host, int index);

// A course folder dropped on the window (or a zip on the page, unpacked): its exercises listed
// first, its first one selected. Returns the line for the Messages panel: what opened, or why not.
StatusLine openCourseFolder(ExercisePanel& panel, const std::filesystem::path& folder);

// The section's contents; `status` receives what happened (the starter copied, why not).
void drawExercisePanel(ExercisePanel& panel, LabHost& host, ShaderEditor& editor, StatusLine& status);

// The inspector's table (and the picture of a clicked value), as the section shows it; with no
// exercise open the window's Inspect panel shows it for the lab's own pass.
void drawInspection(ExercisePanel& panel);

// Asks for the inspector at `pixel` of a viewport of `viewport` pixels (traced between frames).
void requestInspection(ExercisePanel& panel, glm::ivec2 pixel, glm::ivec2 viewport);

// Between the window's frames: traces a requested pixel; starts a requested Check, or draws the next configuration of a
// running one. Returns whether a Check is running (the window keeps drawing while it does).
bool stepExerciseCheck(ExercisePanel& panel, LabHost& host, StatusLine& status);

}  // namespace shadelab
