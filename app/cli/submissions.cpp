#include "app/cli/submissions.h"

#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>

#include "app/shader/preprocessor.h"
#include "app/util/format.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// An entry's name as a relative path inside the submission, or "" when it would leave it.
fs::path safeEntryPath(const std::string& name) {
  if (name.empty() || name[0] == '/' || name[0] == '\\' || name.find('\0') != std::string::npos) return {};
  if (name.size() > 1 && name[1] == ':') return {};  // "C:..."
  fs::path out;
  size_t start = 0;
  while (start <= name.size()) {
    size_t end = name.find_first_of("/\\", start);
    if (end == std::string::npos) end = name.size();
    const std::string part = name.substr(start, end - start);
    if (part == "..") return {};
    if (!part.empty() && part != ".") out /= part;
    start = end + 1;
  }
  return out;
}

void makeReadOnly(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> all;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) all.push_back(it->path());
  for (auto& p : all)
    fs::permissions(p, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    fs::perm_options::remove, ec);
  fs::permissions(dir, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove, ec);
}

}  // namespace

namespace {

struct LayoutRow {
  ClassLayout layout;
  const char* key;   // class.json's word for it
  const char* name;  // how a sentence names it
};
constexpr LayoutRow kLayouts[] = {
    {ClassLayout::Named, "named", "a folder or zip per student, named by the student"},
    {ClassLayout::Moodle, "moodle", "Moodle's \"Download all submissions\""},
    {ClassLayout::Canvas, "canvas", "Canvas's \"Download Submissions\""},
};

const LayoutRow& rowOf(ClassLayout layout) {
  for (auto& row : kLayouts)
    if (row.layout == layout) return row;
  return kLayouts[0];
}

}  // namespace

const char* layoutName(ClassLayout layout) { return rowOf(layout).name; }
const char* layoutKey(ClassLayout layout) { return rowOf(layout).key; }

bool layoutFromKey(const std::string& key, ClassLayout& out) {
  for (auto& row : kLayouts)
    if (key == row.key) {
      out = row.layout;
      return true;
    }
  return false;
}

namespace {

// The student's part of a Moodle download's name: "Ada Lovelace_123_assignsubmission_file_" and
// what follows it (a loose file's own name). Moodle writes the name with its underscores made
// spaces, so the first "_" ends it; a group's name comes first ("Team A-Ada Lovelace").
const std::regex kMoodleName(R"(^([^_]+)_([0-9]+)_assignsubmission_([a-z0-9]+)_?(.*)$)");
// Canvas: the sortable name lower-cased with all but letters, digits and "_" dropped, "_late" when
// late, the user id, the file's id, the file's name as uploaded.
const std::regex kCanvasName(R"(^(?:(.*?)_)?(?:late_)?([0-9]+)_([0-9]+)_(.+)$)");

// Canvas numbers a file a student uploads again under the same name: "pcf-1.glsl". The name the
// student gave it, where no other of their files has it.
std::string canvasUploadName(const std::string& name, const std::set<std::string>& theirs) {
  static const std::regex numbered(R"(^(.+)-[0-9]+(\.[^.]+)$)");
  std::smatch m;
  if (!std::regex_match(name, m, numbered)) return name;
  const std::string plain = m[1].str() + m[2].str();
  return theirs.count(plain) ? name : plain;
}

Submission namedSubmission(std::string name, fs::path source, bool zip) {
  Submission s;
  s.name = std::move(name);
  s.source = std::move(source);
  s.zip = zip;
  return s;
}

std::string readNamed(const fs::path& classDir, std::vector<Submission>& found) {
  std::error_code ec;
  for (fs::directory_iterator it(classDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (it->is_directory(ec))
      found.push_back(namedSubmission(name, it->path(), false));
    else if (it->is_regular_file(ec) && endsWith(name, ".zip") && name.size() > 4)
      found.push_back(namedSubmission(name.substr(0, name.size() - 4), it->path(), true));
  }
  return ec ? classDir.string() + ": " + ec.message() : "";
}

// Every plain file under `dir`, with its path below it.
void filesUnder(const fs::path& dir, std::vector<std::pair<fs::path, std::string>>& files) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && !it->is_symlink(ec))
      files.emplace_back(it->path(), it->path().lexically_relative(dir).generic_string());
}

std::string readDownload(const fs::path& classDir, ClassFolder& out) {
  std::map<std::string, Submission> byId;
  std::map<std::string, std::set<std::string>> names;  // Canvas: each student's upload names
  std::map<fs::path, unsigned long long> fileIds;      // Canvas: each file's id, newest the largest
  std::vector<fs::directory_entry> entries;
  std::error_code ec;
  for (fs::directory_iterator it(classDir, ec), end; !ec && it != end; it.increment(ec))
    if (const std::string n = it->path().filename().string(); !n.empty() && n[0] != '.') entries.push_back(*it);
  if (ec) return classDir.string() + ": " + ec.message();
  std::sort(entries.begin(), entries.end(), [](auto& a, auto& b) { return a.path() < b.path(); });
  const bool moodle = out.layout == ClassLayout::Moodle;
  for (auto& entry : entries) {
    const std::string n = entry.path().filename().string();
    if (entry.is_symlink(ec)) {
      out.ignored.push_back(n + " (a symbolic link; a download holds plain files and folders)");
      continue;
    }
    std::smatch m;
    const bool folder = entry.is_directory(ec);
    if (!std::regex_match(n, m, moodle ? kMoodleName : kCanvasName) || (folder && (!moodle || !m[4].str().empty())) ||
        (!folder && !entry.is_regular_file(ec))) {
      out.ignored.push_back(n + " (not named as " + std::string(layoutName(out.layout)) + " names a student's files)");
      continue;
    }
    const std::string person = moodle ? m[1].str() : m[1].str() == "late" ? "" : m[1].str();
    const std::string id = m[2].str();
    Submission& sub = byId[id];
    if (sub.id.empty()) {
      sub.id = id;
      sub.person = person;
      sub.name = (person.empty() ? std::string(moodle ? "Participant" : "user") : person) + "_" + id;
    }
    if (folder) {
      filesUnder(entry.path(), sub.files);
    } else if (moodle) {
      sub.files.emplace_back(entry.path(), m[4].str());
    } else {
      sub.files.emplace_back(entry.path(), m[4].str());
      names[id].insert(m[4].str());
      fileIds[entry.path()] = std::stoull(m[3].str().substr(0, 18));
    }
  }
  for (auto& [id, sub] : byId) {
    if (!moodle) {
      // The newest upload first (the larger file id): it keeps a name two files would share.
      std::stable_sort(sub.files.begin(), sub.files.end(),
                       [&](auto& a, auto& b) { return fileIds[a.first] > fileIds[b.first]; });
      std::set<std::string> taken;
      for (auto& [path, name] : sub.files) {
        const std::string given = canvasUploadName(name, names[id]);
        if (given != name && !taken.count(given)) {
          sub.notes.push_back(name + " read as " + given + " (Canvas numbers a file uploaded again under its name)");
          name = given;
        } else if (taken.count(name)) {
          sub.notes.push_back(name + ": an older upload under the same name, not taken");
        }
        taken.insert(name);
      }
    }
    out.submissions.push_back(std::move(sub));
  }
  return {};
}

}  // namespace

std::string readClassFolder(const fs::path& classDir, ClassFolder& out) {
  out = ClassFolder{};
  std::error_code ec;
  bool folders = false;
  size_t entries = 0, canvasNames = 0;
  for (fs::directory_iterator it(classDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.empty() || n[0] == '.') continue;
    ++entries;
    if (n.find("_assignsubmission_") != std::string::npos) out.layout = ClassLayout::Moodle;
    if (it->is_directory(ec)) folders = true;
    if (std::regex_match(n, kCanvasName)) ++canvasNames;
  }
  if (ec) return classDir.string() + ": " + ec.message();
  // Canvas's: loose files only, most of them named as Canvas names them (a teacher's own file or
  // two beside them is listed, not graded).
  if (out.layout == ClassLayout::Named && !folders && canvasNames > 0 && 2 * canvasNames > entries)
    out.layout = ClassLayout::Canvas;
  std::vector<Submission>& found = out.submissions;
  if (auto e = out.layout == ClassLayout::Named ? readNamed(classDir, found) : readDownload(classDir, out); !e.empty())
    return e;
  std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.name < b.name; });
  for (size_t i = 1; i < found.size(); ++i)
    if (found[i].name == found[i - 1].name)
      return classDir.string() + ": two submissions are named '" + found[i].name + "' (" +
             found[i - 1].source.filename().string() + " and " + found[i].source.filename().string() + "); rename one";
  return {};
}

std::string stageFiles(const Submission& sub, const fs::path& dest) {
  std::error_code ec;
  if (fs::exists(dest, ec)) return dest.string() + ": already exists; files are only staged into a new folder";
  fs::create_directories(dest, ec);
  for (auto& [path, name] : sub.files) {
    const fs::path relative = safeEntryPath(name);
    if (relative.empty()) continue;  // Moodle's and Canvas's names stay inside; anything else is not taken
    const fs::path target = dest / relative;
    if (fs::exists(target, ec)) continue;  // the first of two with one name, in the download's order
    fs::create_directories(target.parent_path(), ec);
    if (!ec) fs::copy_file(path, target, ec);
    if (ec) return target.string() + ": " + ec.message();
  }
  return {};
}

std::string unpackZip(const fs::path& zipPath, const fs::path& dest, const ZipLimits& limits) {
  const std::string where = zipPath.string();
  int code = 0;
  std::unique_ptr<zip_t, decltype(&zip_discard)> archive(zip_open(zipPath.c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &code),
                                                         zip_discard);
  if (!archive) {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    return where + ": not a zip archive that can be read (" + why + ")";
  }
  const zip_int64_t count = zip_get_num_entries(archive.get(), 0);
  if (count < 0 || size_t(count) > limits.entries)
    return where + ": " + std::to_string(count) + " entries; a submission may hold at most " +
           std::to_string(limits.entries);
  std::error_code ec;
  if (fs::exists(dest, ec)) return dest.string() + ": already exists; a zip is only unpacked into a new folder";
  fs::create_directories(dest, ec);
  if (ec) return dest.string() + ": " + ec.message();

  size_t total = 0;
  std::vector<char> buffer(64 << 10);
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* rawName = zip_get_name(archive.get(), zip_uint64_t(i), ZIP_FL_ENC_GUESS);
    const std::string name = rawName ? rawName : "";
    zip_uint8_t system = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(archive.get(), zip_uint64_t(i), 0, &system, &attributes) == 0 &&
        system == ZIP_OPSYS_UNIX && S_ISLNK(attributes >> 16))
      return where + ": entry '" + name + "' is a symbolic link; a submission holds plain files only";
    const fs::path relative = safeEntryPath(name);
    if (relative.empty()) {
      if (name == "./" || name == "/") continue;
      return where + ": entry '" + name + "' would land outside the submission (an absolute name or a '..')";
    }
    const fs::path target = dest / relative;
    if (endsWith(name, "/") || endsWith(name, "\\")) {
      fs::create_directories(target, ec);
      if (ec) return where + ": entry '" + name + "': " + ec.message();
      continue;
    }
    fs::create_directories(target.parent_path(), ec);
    if (ec) return where + ": entry '" + name + "': " + ec.message();
    if (fs::exists(target, ec)) return where + ": entry '" + name + "' is in the zip twice";
    std::unique_ptr<zip_file_t, decltype(&zip_fclose)> in(zip_fopen_index(archive.get(), zip_uint64_t(i), 0),
                                                          zip_fclose);
    if (!in) return where + ": entry '" + name + "' cannot be read (" + zip_strerror(archive.get()) + ")";
    std::ofstream out(target, std::ios::binary);
    if (!out) return where + ": entry '" + name + "': cannot write " + target.string();
    size_t bytes = 0;
    // The sizes the zip states are not trusted: what is read is counted.
    for (zip_int64_t n; (n = zip_fread(in.get(), buffer.data(), buffer.size())) != 0;) {
      if (n < 0) return where + ": entry '" + name + "' is damaged (" + zip_file_strerror(in.get()) + ")";
      bytes += size_t(n);
      total += size_t(n);
      if (bytes > limits.fileBytes)
        return where + ": entry '" + name + "' unpacks to more than " + std::to_string(limits.fileBytes >> 20) +
               " MB; a shader file is far smaller";
      if (total > limits.totalBytes)
        return where + ": unpacks to more than " + std::to_string(limits.totalBytes >> 20) + " MB in all";
      out.write(buffer.data(), n);
    }
    if (!out.flush()) return where + ": entry '" + name + "': cannot write " + target.string();
  }
  makeReadOnly(dest);
  return {};
}

void removeUnpacked(const fs::path& dir) {
  std::error_code ec;
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec)) fs::permissions(it->path(), fs::perms::owner_all, fs::perm_options::add, ec);
  fs::remove_all(dir, ec);
}

fs::path shaderRootOf(const fs::path& dir) {
  fs::path root = dir;
  for (int depth = 0; depth < 4; ++depth) {
    std::error_code ec;
    std::vector<fs::directory_entry> entries;
    for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename().string()[0] != '.') entries.push_back(*it);
    if (entries.size() != 1 || !entries[0].is_directory(ec)) break;
    const std::string only = entries[0].path().filename().string();
    if (fs::is_directory(builtinShaderDir() / only, ec)) break;  // "shadows/", "common/": the shader tree itself
    root = entries[0].path();
  }
  return root;
}

namespace {

// One plain file of an upload: where it is, and how the notes name it ("my_shaders.zip/common/x.glsl").
struct UploadFile {
  fs::path path;
  std::vector<std::string> parts;  // its path's components under the upload (or the zip)
  std::string shown;
};

std::string lowerCase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Left out of an upload: hidden entries, and the folder macOS adds to every zip it makes.
bool skippedName(const std::string& name) { return name.empty() || name[0] == '.' || name == "__MACOSX"; }

// Every plain file under `root`, as `prefix` + its relative path; symbolic links are listed in `ignored`.
void listUpload(const fs::path& root, const std::string& prefix, std::vector<UploadFile>& files,
                std::vector<std::string>& ignored) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path relative = it->path().lexically_relative(root);
    if (skippedName(it->path().filename().string())) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_symlink(ec)) {
      ignored.push_back(prefix + relative.generic_string() + " (a symbolic link)");
      continue;
    }
    if (!it->is_regular_file(ec)) continue;
    UploadFile f{it->path(), {}, prefix + relative.generic_string()};
    for (auto& part : relative) f.parts.push_back(part.string());
    files.push_back(std::move(f));
  }
  std::sort(files.begin(), files.end(), [](auto& a, auto& b) { return a.shown < b.shown; });
}

// How well an upload's file stands for the rubric's `wanted`: 0 at its path (the last components
// are the rubric's), 1 by its name, 2 by its name in another case, 3 not at all.
int matchOf(const UploadFile& f, const std::vector<std::string>& wanted) {
  if (f.parts.size() >= wanted.size() && std::equal(wanted.rbegin(), wanted.rend(), f.parts.rbegin())) return 0;
  if (f.parts.back() == wanted.back()) return 1;
  if (lowerCase(f.parts.back()) == lowerCase(wanted.back())) return 2;
  return 3;
}

// "a, b and c", at most ten named.
std::string namesOf(const std::vector<std::string>& names) { return englishList(names, "", 10); }

}  // namespace

std::string placeUpload(const fs::path& upload, const std::vector<std::string>& files, const fs::path& dest,
                        const std::string& shown, Placement& out) {
  std::error_code ec;
  if (!fs::is_directory(upload, ec)) return upload.string() + ": not a folder; an upload is placed from its folder";
  if (fs::exists(dest, ec)) return dest.string() + ": already exists; an upload is only placed into a new folder";
  fs::create_directories(dest, ec);
  if (ec) return dest.string() + ": " + ec.message();
  out = Placement{};

  std::vector<UploadFile> found;
  std::vector<std::string> ignored;
  listUpload(upload, "", found, ignored);
  // A zip in the upload: its files count as the upload's, named through it.
  const fs::path zips = dest.parent_path() / (dest.filename().string() + ".zips");
  std::vector<UploadFile> unzipped;
  int k = 0;
  for (auto it = found.begin(); it != found.end();) {
    if (lowerCase(fs::path(it->shown).extension().string()) != ".zip") {
      ++it;
      continue;
    }
    const fs::path into = zips / std::to_string(k++);
    if (auto e = unpackZip(it->path, into); !e.empty()) {
      out.notes.push_back("not unpacked: " + e.substr(e.find(": ") + 2) + " (" + it->shown + ")");
    } else {
      std::vector<UploadFile> inside;
      listUpload(into, it->shown + "/", inside, ignored);
      for (auto& f : inside)
        if (lowerCase(f.path.extension().string()) == ".zip") {
          ignored.push_back(f.shown + " (a zip inside a zip)");
        } else {
          unzipped.push_back(std::move(f));
        }
    }
    it = found.erase(it);
  }
  found.insert(found.end(), unzipped.begin(), unzipped.end());

  std::set<size_t> considered;  // every file that stood for one of `files`
  for (auto& file : files) {
    std::vector<std::string> wanted;
    for (auto& part : fs::path(file)) wanted.push_back(part.string());
    std::vector<std::pair<std::pair<int, size_t>, size_t>> candidates;  // (rule, depth), index
    for (size_t i = 0; i < found.size(); ++i)
      if (int m = matchOf(found[i], wanted); m < 3) candidates.push_back({{m, found[i].parts.size()}, i});
    std::stable_sort(candidates.begin(), candidates.end(), [](auto& a, auto& b) { return a.first < b.first; });
    if (candidates.empty()) {
      out.missing.push_back(file);
      continue;
    }
    const auto [rank, index] = candidates.front();
    const UploadFile& taken = found[index];
    const fs::path target = dest / file;
    fs::create_directories(target.parent_path(), ec);
    if (!ec) fs::copy_file(taken.path, target, ec);
    if (ec) return target.string() + ": " + ec.message();
    for (auto& c : candidates) considered.insert(c.second);
    static const char* how[] = {"at its path", "by its name", "by its name in another case"};
    if (rank.first != 0 || taken.shown != file) {
      if (rank.first == 0)
        out.notes.push_back(file + ": taken from " + taken.shown);
      else
        out.notes.push_back(file + ": " + taken.shown + " taken " + how[rank.first]);
    }
    if (candidates.size() > 1) {
      std::vector<std::string> others;
      for (size_t i = 1; i < candidates.size(); ++i) others.push_back(found[candidates[i].second].shown);
      const auto& next = candidates[1].first;
      const std::string why = next.first != rank.first ? std::string("found ") + how[rank.first]
                              : next.second != rank.second
                                  ? "the shallower of those found " + std::string(how[rank.first])
                                  : "the first by name of those found " + std::string(how[rank.first]);
      out.notes.push_back(std::to_string(candidates.size()) + " files could be " + file + ": took " + taken.shown +
                          " (" + why + "), not " + namesOf(others));
    }
  }
  for (size_t i = 0; i < found.size(); ++i)
    if (!considered.count(i)) ignored.push_back(found[i].shown);
  if (!ignored.empty()) out.notes.push_back("ignored, not among the exercise's files: " + namesOf(ignored));
  if (!out.missing.empty())
    out.notes.push_back("not in the upload: " + namesOf(out.missing) +
                        " (looked for at that path, then by name in any case, in every folder of " + shown +
                        (k > 0 ? " and of the zips in it)" : ")"));
  removeUnpacked(zips);
  return {};
}

}  // namespace shadelab
