// The Exercises section of the window (and of the page): every exercise with its statement, a
// button that puts the starter into the student's folder and opens it in the editor, and Check,
// which runs the exercise's rubric in place (grade/exercise_check.h) and shows the grader's lines:
// one per check, PASS / PARTIAL / FAIL, the hint under each that lost points, and the total.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "app/grade/exercise_check.h"
#include "app/ui/status_line.h"

namespace shadelab {

class LabHost;
struct ShaderEditor;

struct ExercisePanel {
  std::vector<std::string> ids;      // every exercise, read once, grouped by lab, then level
  std::vector<std::string> headers;  // "shadows: from scratch" above the first of each group, else ""
  bool listed = false;
  std::string selected;   // the exercise shown ("" = none)
  std::string statement;  // its statement.md
  bool showStatement = false;
  bool checkRequested = false;  // --check / the link's "check": press Check on the next frame
  bool reveal = false;          // a Check started: the panel scrolls to its results until it ends
  ExerciseCheck check;

  void select(const std::string& id);
};

// A course folder dropped on the window (or a zip on the page, unpacked): its exercises listed
// first, its first one selected. Returns the line for the Messages panel: what opened, or why not.
StatusLine openCourseFolder(ExercisePanel& panel, const std::filesystem::path& folder);

// The section's contents; `status` receives what happened (the starter copied, why not).
void drawExercisePanel(ExercisePanel& panel, LabHost& host, ShaderEditor& editor, StatusLine& status);

// Between the window's frames: starts a requested Check, or draws the next configuration of a
// running one. Returns whether a Check is running (the window keeps drawing while it does).
bool stepExerciseCheck(ExercisePanel& panel, LabHost& host, StatusLine& status);

}  // namespace shadelab
