#include "app/ui/shader_editor.h"

#include <imgui.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "app/host/lab_host.h"
#include "app/measure/report.h"
#include "app/ui/platform.h"
#include "app/util/contained_path.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"
#include "app/util/zip_writer.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr double kSaveAfterSeconds = 0.4;  // after the last keystroke: every pause recompiles

// ImGui's multiline input on a std::string: the string grows as the user types.
int resizeCallback(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
    auto* text = static_cast<std::string*>(data->UserData);
    text->resize(size_t(data->BufTextLen));
    data->Buf = text->data();
  }
  return 0;
}

// The student's copy of the open file: inside their folder, whatever the name says.
fs::path copyOf(const ShaderEditor& e) {
  const fs::path name = containedName(e.rel);
  return name.empty() ? fs::path() : e.folder / name;
}

StatusLine save(ShaderEditor& e) {
  const fs::path file = copyOf(e);
  if (file.empty()) return StatusLine::failed("'" + e.rel + "' is not a name inside your folder");
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << e.text;
  if (!out.flush()) return StatusLine::failed("could not save " + file.string());
  e.saved = e.text;
  e.lastEdit = -1.0;
  persistStudentFiles();
  return StatusLine::done("saved " + file.string());
}

StatusLine downloadZip(const fs::path& folder) {
  std::vector<ZipEntry> entries;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec))
      entries.push_back({it->path().lexically_relative(folder).generic_string(), readWholeFile(it->path())});
  std::sort(entries.begin(), entries.end(), [](auto& a, auto& b) { return a.name < b.name; });
  if (entries.empty()) return StatusLine::failed("nothing to download: you have not edited a file yet");
  const fs::path zip = freshName("shaders", "my-shaders", ".zip");
  if (auto err = writeTextFile(zip.string(), storedZip(entries)); !err.empty()) return StatusLine::failed(err);
  offerDownload(zip.string());
  return StatusLine::done("saved " + zip.string() + " (" + std::to_string(entries.size()) + " files)");
}

}  // namespace

void ShaderEditor::open(LabHost& host, const std::string& relPath) {
  rel = relPath;
  // The student's own copy when there is one, whether or not their folder is searched now (the
  // page's "builtin"): an edit is saved over that copy, so it must start from it.
  const fs::path mine = copyOf(*this);
  std::error_code ec;
  const bool hasCopy = !mine.empty() && fs::is_regular_file(mine, ec);
  text = saved = readWholeFile(hasCopy ? mine : host.shaders().searchPath().resolve(relPath));
  lastEdit = -1.0;
}

void drawEditableFiles(ShaderEditor& editor, LabHost& host) {
  if (editor.folder.empty()) {
    ImGui::TextDisabled("Start with --shaders DIR to edit files here (they are saved into DIR).");
    return;
  }
  std::set<std::string> files;
  for (auto& p : host.lab().activePrograms())
    for (auto& rel : p->relPaths()) files.insert(rel);
  ImGui::TextUnformatted("Edit (saved into your folder, the lab's files stay as they are):");
  std::vector<std::string> order = editor.exerciseFiles;
  for (auto& rel : files)
    if (std::find(order.begin(), order.end(), rel) == order.end()) order.push_back(rel);
  for (size_t i = 0; i < order.size(); ++i) {
    const std::string& rel = order[i];
    std::error_code ec;
    const fs::path name = containedName(rel);
    const bool mine = !name.empty() && fs::exists(editor.folder / name, ec);
    const bool exercise = i < editor.exerciseFiles.size();
    ImGui::PushID(rel.c_str());
    if (ImGui::SmallButton("Edit")) editor.open(host, rel);
    ImGui::SameLine();
    ImGui::Text("%s%s%s", rel.c_str(), mine ? "  (yours)" : "", exercise ? "  (the exercise)" : "");
    ImGui::PopID();
  }
}

void drawShaderEditor(ShaderEditor& editor, LabHost& host, StatusLine& status) {
  if (editor.rel.empty() || editor.folder.empty()) return;
  const double now = ImGui::GetTime();
  if (editor.lastEdit >= 0.0 && now - editor.lastEdit >= kSaveAfterSeconds && editor.text != editor.saved)
    status = save(editor);
  ImGui::SetNextWindowSize({640, 520}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);  // code over the picture would be hard to read
  bool open = true;
  ImGui::Begin(("Editor: " + editor.rel + "###shader-editor").c_str(), &open);
  const fs::path mine = copyOf(editor);
  std::error_code ec;
  const bool hasCopy = !mine.empty() && fs::exists(mine, ec);
  ImGui::TextDisabled(
      "%s", hasCopy ? mine.string().c_str() : "the lab's file: your first edit saves a copy into your folder");
  if (hasCopy) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Use the lab's file")) {
      fs::remove(mine, ec);
      persistStudentFiles();
      editor.open(host, editor.rel);
      status = ec ? StatusLine::failed("could not remove " + mine.string())
                  : StatusLine::done("removed " + mine.string() + ": the lab's file serves it again");
    }
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Download my shaders (.zip)")) status = downloadZip(editor.folder);
  if (ImGui::InputTextMultiline("##text", editor.text.data(), editor.text.capacity() + 1, ImVec2(-1, -1),
                                ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackResize, resizeCallback,
                                &editor.text))
    editor.lastEdit = now;
  ImGui::End();
  if (!open) {
    if (editor.text != editor.saved) status = save(editor);
    editor.rel.clear();
  }
}

}  // namespace shadelab
