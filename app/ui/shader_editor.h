// The in-app shader editor: any file of the current lab's programs, edited in a window of its own.
// An edit is saved into the student's folder (the first --shaders folder; in the page, its own
// folder kept in the browser's storage) a moment after the last keystroke, and the file watcher
// rebuilds every program that reads it: errors show at file:line:col in the Shaders panel, and the
// last good program keeps drawing. The built-in file is never written; "Use the lab's file" removes
// the student's copy. "Download my shaders" zips the student's folder, laid out like shaders/.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "app/ui/status_line.h"

namespace shadelab {

class LabHost;

struct ShaderEditor {
  std::filesystem::path folder;            // where edits are saved; empty: editing is off (no --shaders folder)
  std::string rel;                         // the file open in the editor ("shading/shade.frag"); "" = closed
  std::string text;                        // as edited
  std::string saved;                       // as last saved (or as opened)
  double lastEdit = -1.0;                  // seconds (ImGui's clock) of the last unsaved keystroke
  std::vector<std::string> exerciseFiles;  // the open exercise's files: listed first, whatever the lab draws

  // Opens `relPath` with the text that serves it now (the student's copy, or the lab's own file).
  void open(LabHost& host, const std::string& relPath);
};

// The list of the active programs' files with an Edit button each, for the Shaders panel: the open
// exercise's files first.
void drawEditableFiles(ShaderEditor& editor, LabHost& host);
// The editor's window, when a file is open; `status` receives what happened (saved, removed, ...).
void drawShaderEditor(ShaderEditor& editor, LabHost& host, StatusLine& status);

}  // namespace shadelab
