// A class's submissions: each subfolder of the class folder, or each .zip in it, is one student's,
// named by the folder or the file. A zip is unpacked into a private folder first; what is in it is
// untrusted, so unpacking refuses any entry that would land outside that folder (an absolute
// name, a "..", a symbolic link), and stops at limits on entries and bytes (a zip bomb costs its
// own submission only).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab {

struct Submission {
  std::string name;              // the folder's name, or the zip's without ".zip"
  std::filesystem::path source;  // the folder or the zip
  bool zip = false;
};

struct ZipLimits {
  size_t entries = 2000;
  size_t fileBytes = size_t(16) << 20;   // one file, unpacked
  size_t totalBytes = size_t(64) << 20;  // all files, unpacked
};

// The submissions in `classDir`, sorted by name. Hidden entries and other files are skipped. ""
// or why the folder cannot be graded (two submissions with one name, e.g. ana/ and ana.zip).
std::string listSubmissions(const std::filesystem::path& classDir, std::vector<Submission>& out);

// Unpacks `zip` into `dest` (created; must not exist yet). The files are left read-only. "" or
// one line naming the zip and the entry at fault.
std::string unpackZip(const std::filesystem::path& zip, const std::filesystem::path& dest,
                      const ZipLimits& limits = {});

// Removes a folder unpackZip made (its read-only files and folders included).
void removeUnpacked(const std::filesystem::path& dir);

// The folder that holds the shader files: `dir` itself, or the one folder in it when that is all
// it holds and it is not one of the lab's shader folders (students zip "ana/shadows/pcf.glsl" as
// often as "shadows/pcf.glsl").
std::filesystem::path shaderRootOf(const std::filesystem::path& dir);

}  // namespace shadelab
