#include "app/cli/submissions.h"

#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <fstream>
#include <memory>

#include "app/shader/preprocessor.h"

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

std::string listSubmissions(const fs::path& classDir, std::vector<Submission>& out) {
  std::error_code ec;
  std::vector<Submission> found;
  for (fs::directory_iterator it(classDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (it->is_directory(ec))
      found.push_back({name, it->path(), false});
    else if (it->is_regular_file(ec) && endsWith(name, ".zip") && name.size() > 4)
      found.push_back({name.substr(0, name.size() - 4), it->path(), true});
  }
  if (ec) return classDir.string() + ": " + ec.message();
  std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.name < b.name; });
  for (size_t i = 1; i < found.size(); ++i)
    if (found[i].name == found[i - 1].name)
      return classDir.string() + ": two submissions are named '" + found[i].name + "' (" +
             found[i - 1].source.filename().string() + " and " + found[i].source.filename().string() + "); rename one";
  out = std::move(found);
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

}  // namespace shadelab
