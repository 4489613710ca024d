#include "app/grade/solution_cache.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMagic = "SHADELAB-SOLUTION 3\n";
constexpr std::string_view kFramesMagic = "SHADELAB-FRAMES 1\n";
constexpr size_t kMostEntryBytes = size_t(128) << 20;
constexpr int kMaxSide = 16384;

template <typename T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Reads from a byte string, failing (rather than reading past the end) on anything short.
struct Reader {
  std::string_view bytes;
  size_t at = 0;
  bool take(void* dst, size_t n) {
    if (n > bytes.size() - at) return false;
    std::memcpy(dst, bytes.data() + at, n);
    at += n;
    return true;
  }
  template <typename T>
  bool get(T& v) {
    return take(&v, sizeof v);
  }
};

void putImage(std::string& out, const ImageF& image) {
  put<int32_t>(out, image.size.x);
  put<int32_t>(out, image.size.y);
  out.append(reinterpret_cast<const char*>(image.rgba.data()), image.rgba.size() * sizeof(float));
}

bool getImage(Reader& in, ImageF& image) {
  int32_t w = 0, h = 0;
  if (!in.get(w) || !in.get(h) || w < 1 || h < 1 || w > kMaxSide || h > kMaxSide) return false;
  const size_t floats = size_t(w) * size_t(h) * 4;
  if (floats * sizeof(float) > in.bytes.size() - in.at) return false;
  image.size = {w, h};
  image.rgba.resize(floats);
  return in.take(image.rgba.data(), floats * sizeof(float));
}

// An entry's bytes, mapped rather than read into a string: an entry is tens of megabytes and each
// grading child reads one, whose images are copied out of the map once.
class MappedFile {
 public:
  explicit MappedFile(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    struct stat st {};
    if (::fstat(fd, &st) == 0 && st.st_size > 0) {
      void* at = ::mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
      if (at != MAP_FAILED) {
        data_ = static_cast<const char*>(at);
        size_ = size_t(st.st_size);
      }
    }
    ::close(fd);
  }
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  bool mapped() const { return data_ != nullptr; }
  std::string_view bytes() const { return {data_ ? data_ : "", size_}; }

 private:
  const char* data_ = nullptr;
  size_t size_ = 0;
};

// An entry opened: its bytes (mapped, or read where a file system cannot map them), its kind's
// magic checked and its JSON parsed; `in` stands after the JSON. Not `ok` when any of it fails.
struct OpenedEntry {
  OpenedEntry(const fs::path& file, std::string_view magic) : mapped(file) {
    if (!mapped.mapped() && !readWholeFile(file, read)) return;
    const std::string_view bytes = mapped.mapped() ? mapped.bytes() : std::string_view(read);
    in.bytes = bytes;
    uint32_t jsonBytes = 0;
    if (bytes.compare(0, magic.size(), magic) != 0) return;
    in.at = magic.size();
    if (!in.get(jsonBytes) || jsonBytes > bytes.size() - in.at) return;
    numbers = nlohmann::json::parse(bytes.substr(in.at, jsonBytes), nullptr, false);
    in.at += jsonBytes;
    ok = !numbers.is_discarded();
  }
  bool atEnd() const { return in.at == in.bytes.size(); }
  MappedFile mapped;
  std::string read;
  Reader in;
  nlohmann::json numbers;
  bool ok = false;
};

// An entry's first bytes: its kind's magic and its JSON.
std::string entryHead(std::string_view magic, const nlohmann::json& numbers) {
  std::string bytes(magic);
  const std::string json = numbers.dump();
  put<uint32_t>(bytes, uint32_t(json.size()));
  return bytes += json;
}

}  // namespace

ContentHash& ContentHash::add(std::string_view bytes) {
  // Two FNV-1a lanes with different multipliers and offsets: 128 bits between them.
  for (unsigned char c : bytes) {
    a_ = (a_ ^ c) * 0x100000001b3ull;       // FNV's 64-bit prime
    b_ = (b_ ^ c) * 0x9e3779b97f4a7c15ull;  // odd: 2^64 / golden ratio
  }
  return *this;
}

ContentHash& ContentHash::addFile(const fs::path& file) {
  std::string bytes;
  if (!readWholeFile(file, bytes)) return add("\x01(unreadable)\x01");
  return add(std::to_string(bytes.size()) + ":").add(bytes);
}

ContentHash& ContentHash::addTree(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(it->path().lexically_relative(dir));
  std::sort(files.begin(), files.end());
  add(std::to_string(files.size()) + " files\n");
  for (auto& f : files) add(f.generic_string() + "\n").addFile(dir / f);
  return *this;
}

std::string ContentHash::hex() const {
  char s[33];
  std::snprintf(s, sizeof s, "%016llx%016llx", static_cast<unsigned long long>(a_),
                static_cast<unsigned long long>(b_));
  return s;
}

SolutionCache::SolutionCache(fs::path dir, uint64_t budgetBytes) : dir_(std::move(dir)), budget_(budgetBytes) {}

uint64_t SolutionCache::defaultBudgetBytes() {
  constexpr uint64_t kMiB = 1024 * 1024;
  if (const char* env = std::getenv("SHADELAB_CACHE_MB"); env && *env) {
    char* end = nullptr;
    const unsigned long long mb = std::strtoull(env, &end, 10);
    if (end != env && *end == '\0' && mb >= 1 && mb < (1ull << 40)) return mb * kMiB;
  }
  return 4096 * kMiB;
}

void SolutionCache::prune(const fs::path& keep) const {
  struct Entry {
    fs::path path;
    uint64_t bytes;
    fs::file_time_type used;
  };
  std::vector<Entry> entries;
  uint64_t total = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() != ".bin" || !it->is_regular_file(ec)) continue;
    const uint64_t bytes = it->file_size(ec);
    if (ec) continue;
    const fs::file_time_type used = it->last_write_time(ec);
    if (ec) continue;
    entries.push_back({it->path(), bytes, used});
    total += bytes;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (auto& e : entries) {
    if (total <= budget_) break;
    if (e.path == keep) continue;
    // Another process may have removed it, or be reading it (it keeps its open file): either is fine.
    fs::remove(e.path, ec);
    if (!ec) total -= e.bytes;
  }
}

fs::path SolutionCache::file(const std::string& key) const { return dir_ / (key + ".bin"); }

void SolutionCache::markUsed(const std::string& key) const {
  std::error_code ec;
  fs::last_write_time(file(key), fs::file_time_type::clock::now(), ec);  // used: the last to be pruned
}

std::string SolutionCache::write(const std::string& key, const std::string& bytes) const {
  // An entry of a large rubric size could pass a grading child's file-size limit (grade/watchdog.h):
  // it is drawn again where needed rather than kept.
  if (bytes.size() > kMostEntryBytes) return {};
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) return "the solution cache " + dir_.string() + ": " + ec.message();
  // Another process may be writing the same entry: each writes its own file and the last rename wins.
  const fs::path temp = dir_ / (key + ".tmp-" + std::to_string(getpid()));
  {
    std::ofstream out(temp, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) {
      fs::remove(temp, ec);
      return "the solution cache " + temp.string() + ": could not write";
    }
  }
  fs::rename(temp, file(key), ec);
  if (ec) {
    fs::remove(temp, ec);
    return "the solution cache " + file(key).string() + ": " + ec.message();
  }
  prune(file(key));
  return {};
}

bool SolutionCache::load(const std::string& key, CachedSolution& out) const {
  if (!enabled()) return false;
  OpenedEntry e(file(key), kMagic);
  uint32_t truths = 0, mistakes = 0, slips = 0;
  if (!e.ok || !e.numbers.is_object() || !e.in.get(truths) || !e.in.get(mistakes) || !e.in.get(slips) || truths > 64 ||
      mistakes > 256 || slips > 256)
    return false;
  CachedSolution entry;
  entry.numbers = std::move(e.numbers);
  if (!getImage(e.in, entry.frame)) return false;
  entry.truths.resize(truths);
  entry.mistakes.resize(mistakes);
  entry.slips.resize(slips);
  for (auto* images : {&entry.truths, &entry.mistakes, &entry.slips})
    for (auto& image : *images)
      if (!getImage(e.in, image)) return false;
  if (!e.atEnd()) return false;
  markUsed(key);
  out = std::move(entry);
  return true;
}

std::string SolutionCache::store(const std::string& key, const CachedSolution& entry) const {
  if (!enabled()) return {};
  std::string bytes = entryHead(kMagic, entry.numbers);
  put<uint32_t>(bytes, uint32_t(entry.truths.size()));
  put<uint32_t>(bytes, uint32_t(entry.mistakes.size()));
  put<uint32_t>(bytes, uint32_t(entry.slips.size()));
  putImage(bytes, entry.frame);
  for (auto* images : {&entry.truths, &entry.mistakes, &entry.slips})
    for (auto& image : *images) putImage(bytes, image);
  return write(key, bytes);
}

bool SolutionCache::load(const std::string& key, CachedFrames& out) const {
  if (!enabled()) return false;
  OpenedEntry e(file(key), kFramesMagic);
  uint32_t frames = 0;
  if (!e.ok || !e.in.get(frames) || frames > 256) return false;
  CachedFrames entry;
  entry.numbers = std::move(e.numbers);
  entry.frames.resize(frames);
  for (auto& image : entry.frames)
    if (!getImage(e.in, image)) return false;
  if (!e.atEnd()) return false;
  markUsed(key);
  out = std::move(entry);
  return true;
}

std::string SolutionCache::store(const std::string& key, const CachedFrames& entry) const {
  if (!enabled()) return {};
  std::string bytes = entryHead(kFramesMagic, entry.numbers);
  put<uint32_t>(bytes, uint32_t(entry.frames.size()));
  for (auto& image : entry.frames) putImage(bytes, image);
  return write(key, bytes);
}

fs::path defaultSolutionCacheDir() {
  if (const char* env = std::getenv("SHADELAB_CACHE"); env && *env) return fs::path(env) / "solutions";
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "shadelab" / "solutions";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "shadelab" / "solutions";
  return {};
}

}  // namespace shadelab
