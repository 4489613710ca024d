// A class's submissions: each subfolder of the class folder, or each .zip in it, is one student's,
// named by the folder or the file, or each student's files in Moodle's or Canvas's download of an
// assignment; then each upload's files put where the rubric expects them (placeUpload), for
// `grade --class` and every platform's entry point alike. A zip is unpacked into a private folder
// first; what is in it is untrusted, so unpacking refuses any entry that would land outside that
// folder (an absolute name, a "..", a symbolic link), and stops at limits on entries and bytes (a
// zip bomb costs its own submission only).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab {

// How a class folder is laid out: a folder or zip per student named by the student, or the
// download a platform makes of one assignment's submissions, read as it comes (unzipped).
enum class ClassLayout {
  Named,   // ana/, ana.zip: the name is the student's username or login
  Moodle,  // "Download all submissions": a folder "Ada Lovelace_123_assignsubmission_file_/" per
           // student and submission plugin, or ("in folders" off) loose files
           // "Ada Lovelace_123_assignsubmission_file_pcf.glsl"; 123 is the participant id
  Canvas,  // "Download Submissions": loose files "lovelaceada_4567_8910_pcf.glsl" ("_late" after the
           // name when late); 4567 is the student's Canvas user id, 8910 the file's
};
const char* layoutName(ClassLayout layout);                    // "Moodle's \"Download all submissions\"", ...
const char* layoutKey(ClassLayout layout);                     // "named", "moodle", "canvas": class.json's word
bool layoutFromKey(const std::string& key, ClassLayout& out);  // false for a word none of those

struct Submission {
  std::string name;              // the folder's name, or the zip's without ".zip"; in a platform's
                                 // download, the student's part of the names ("Ada Lovelace_123")
  std::filesystem::path source;  // the folder or the zip; "" where `files` lists the upload instead
  bool zip = false;
  // A platform's download: the student's files, each with the name it had in their upload
  // ("shaders/pcf.glsl" under a Moodle folder, "pcf.glsl" for Canvas's "..._8910_pcf.glsl").
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  std::string id, person;          // the platform's identity for them and how it names them
  std::vector<std::string> notes;  // how the download's names were read, for the report
};

struct ZipLimits {
  size_t entries = 2000;
  size_t fileBytes = size_t(16) << 20;   // one file, unpacked
  size_t totalBytes = size_t(64) << 20;  // all files, unpacked
};

// A class folder as read: its layout, its submissions sorted by name, and the entries of a
// platform's download that belong to no student (each with why).
struct ClassFolder {
  ClassLayout layout = ClassLayout::Named;
  std::vector<Submission> submissions;
  std::vector<std::string> ignored;
};

// Reads `classDir`. A platform's download is recognised by its names: any entry holding
// "_assignsubmission_" is Moodle's (its folders end "_file_" or "_file", Moodle 3 and 4); loose
// files only, most of them named "name_USERID_FILEID_file", Canvas's (of two files with one name,
// the newer upload is taken, and a note says so).
// Otherwise every subfolder and every .zip is one student's; hidden entries and other files are
// skipped. "" or why the folder cannot be graded (two submissions with one name, e.g. ana/ and ana.zip).
std::string readClassFolder(const std::filesystem::path& classDir, ClassFolder& out);

// Copies a download's `files` into `dest` (made afresh) under their upload names, so the upload
// is placed as a folder would be. "" or why not.
std::string stageFiles(const Submission& sub, const std::filesystem::path& dest);

// Unpacks `zip` into `dest` (created; must not exist yet). The files are left read-only. "" or
// one line naming the zip and the entry at fault.
std::string unpackZip(const std::filesystem::path& zip, const std::filesystem::path& dest,
                      const ZipLimits& limits = {});

// Removes a folder unpackZip made (its read-only files and folders included).
void removeUnpacked(const std::filesystem::path& dir);

// How an upload's files were put where the exercises expect them (placeUpload).
struct Placement {
  std::vector<std::string> notes;    // for the report: what was taken from where and why, ignored, missing
  std::vector<std::string> missing;  // the exercises' files found nowhere in the upload
};

// Puts each of `files` (paths under a shader root: "common/specular.glsl") from `upload`, a
// student's folder as they made it, into `dest` (made afresh; must not exist), at its path there.
// A file is taken
//   1. at its path, under the upload or any folder in it ("my_shaders/common/specular.glsl"),
//   2. else by its name, anywhere ("specular.glsl" dropped at the top: a flat upload),
//   3. else by its name in another case ("Specular.GLSL").
// A .zip in the upload is unpacked first (unpackZip's limits), so a zip of a folder counts with or
// without its top folder. Where two files would do, the earlier rule wins, then the shallower,
// then the first by name, and a note says which was taken and why; every other file is ignored and
// listed; a file found nowhere is named with where it was looked for. Hidden entries, __MACOSX/ and
// symbolic links are skipped. `shown` names the upload in the notes ("ana.zip"). "" or why the
// upload could not be read; a zip inside it that is refused is a note, not an error.
std::string placeUpload(const std::filesystem::path& upload, const std::vector<std::string>& files,
                        const std::filesystem::path& dest, const std::string& shown, Placement& out);

// The folder that holds the shader files: `dir` itself, or the one folder in it when that is all
// it holds and it is not one of the lab's shader folders (students zip "ana/shadows/pcf.glsl" as
// often as "shadows/pcf.glsl").
std::filesystem::path shaderRootOf(const std::filesystem::path& dir);

}  // namespace shadelab
