#include "app/host/soak.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include "app/gl/handle.h"
#include "app/host/random_settings.h"
#include "app/measure/report.h"
#include "app/scene/scene_catalog.h"
#include "app/util/csv.h"
#include "app/util/format.h"
#include "app/util/output_files.h"
#include "app/util/process_memory.h"
#include "app/util/read_file.h"

namespace fs = std::filesystem;

namespace shadelab {
namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Meshes a user might drop: the project's test files, and the shared data where it exists.
std::vector<fs::path> droppableMeshes() {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const fs::path& dir : {fs::path(SHADELAB_SOURCE_DIR) / "tests" / "data", dataDirectory() / "meshes"}) {
    if (dir.empty()) continue;
    for (auto& e : fs::directory_iterator(dir, ec)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file(ec) && (ext == ".gltf" || ext == ".off" || ext == ".obj" || ext == ".ply") &&
          e.file_size(ec) < (8u << 20))
        out.push_back(e.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Least-squares slope of y over x.
double leastSquaresSlope(const std::vector<std::pair<double, double>>& xy) {
  double mx = 0, my = 0;
  for (auto& [x, y] : xy) mx += x, my += y;
  mx /= double(xy.size()), my /= double(xy.size());
  double num = 0, den = 0;
  for (auto& [x, y] : xy) num += (x - mx) * (y - my), den += (x - mx) * (x - mx);
  return den > 0 ? num / den : 0.0;
}

// "scene S --lab L --set ...": where the host is now, as a command line reproduces it.
std::string describeState(LabHost& host) {
  return "scene " + host.sceneId() + " --lab " + std::string(host.lab().id()) + " " +
         settingsAsArgs(host.lab().id(), host.currentSettings());
}

}  // namespace

SoakDriver::SoakDriver(fs::path scratch, unsigned seed)
    : scratch_(std::move(scratch)), rng_(seed), start_(now()), meshes_(droppableMeshes()) {}

fs::path SoakDriver::makeScratch() {
  const fs::path dir = freshName("soak", "shaders", "");
  fs::create_directories(dir);
  return dir;
}

double SoakDriver::seconds() const { return now() - start_; }

std::string SoakDriver::step(LabHost& host) {
  ++steps_;
  if (!brokenFile_.empty()) {  // a broken file is fixed at the next step, as a student would
    breakOrFixShader(host);
    return "fixed " + brokenFile_;
  }
  const int dice = std::uniform_int_distribution<int>(0, 99)(rng_);
  if (dice < 10) {
    switchLab(host);
    return "switched to " + std::string(host.lab().id());
  }
  if (dice < 20) {
    breakOrFixShader(host);
    return brokenFile_.empty() ? "no shader to break" : "broke " + brokenFile_;
  }
  if (dice < 30) {
    loadOrDropMesh(host);
    return "scene " + host.sceneId();
  }
  if (dice < 45) {  // jobs started and superseded: two draws in a row, a frame between them
    ++supersedes_;
    host.applySettings(randomSettings(host.lab(), rng_, 0.3));
    host.renderFrame({160, 90});
    afterFrame(host, false);
    host.applySettings(randomSettings(host.lab(), rng_, 0.3));
    return "superseded";
  }
  if (dice < 50) {
    settle(host);
    return "settled";
  }
  if (dice < 53) {
    host.resetParams();
    return "reset";
  }
  const std::string err = host.applySettings(randomSettings(host.lab(), rng_, 0.3));
  return err.empty() ? "random parameters" : "random parameters: " + err;
}

void SoakDriver::settle(LabHost& host) {
  const double start = seconds();
  host.settle();
  lastFrameAt_ += seconds() - start;  // waiting for every job is the soak's doing, not a slow frame
}

void SoakDriver::switchLab(LabHost& host) {
  const auto ids = labIds();
  const std::string id = ids[std::uniform_int_distribution<size_t>(0, ids.size() - 1)(rng_)];
  leftState_ = describeState(host);
  if (auto err = host.selectLab(id); !err.empty()) problems_.push_back("switch to " + id + ": " + err);
  ++labSwitches_;
  countAfterSwitch_ = true;  // counted after the new lab's first frame
}

void SoakDriver::breakOrFixShader(LabHost& host) {
  if (!brokenFile_.empty()) {
    fs::remove(scratch_ / brokenFile_);  // the built-in file serves again
    brokenFile_.clear();
    return;
  }
  const auto programs = host.lab().activePrograms();
  if (programs.empty()) return;
  const auto& stages = programs[std::uniform_int_distribution<size_t>(0, programs.size() - 1)(rng_)]->spec().stages;
  if (stages.empty()) return;
  const std::string rel = stages[std::uniform_int_distribution<size_t>(0, stages.size() - 1)(rng_)].path;
  std::string text = readWholeFile(builtinShaderDir() / rel);
  const size_t main = text.find("void main");
  if (main == std::string::npos) return;
  text.insert(main, "this is not GLSL;\n");  // a typo a student makes
  fs::create_directories((scratch_ / rel).parent_path());
  if (!writeTextFile((scratch_ / rel).string(), text).empty()) return;
  brokenFile_ = rel;
  ++shaderEdits_;
}

void SoakDriver::loadOrDropMesh(LabHost& host) {
  const std::string home(host.lab().defaultScene());
  if (host.sceneId() != home) {  // drop what was loaded
    host.selectScene(home);
    return;
  }
  std::vector<std::string> choices;
  for (auto& s : host.lab().scenes()) choices.push_back(s.id);
  for (auto& f : meshes_) choices.push_back(f.string());
  if (choices.empty()) return;
  ++meshLoads_;
  const std::string pick = choices[std::uniform_int_distribution<size_t>(0, choices.size() - 1)(rng_)];
  host.selectScene(pick);  // a file the lab cannot use is refused with a message and nothing changes
}

void SoakDriver::afterFrame(LabHost& host, bool readPixels) {
  ++frames_;
  if (const std::string err = gl::drainErrors(); !err.empty() && ++glErrors_ <= 5)
    problems_.push_back("GL error " + err + ": " + describeState(host));
  if (readPixels)
    if (const size_t bad = countNonFinite(host.readImage()); bad > 0 && ++nonFiniteFrames_ <= 5)
      problems_.push_back(std::to_string(bad) + " NaN/Inf values: " + describeState(host));
  if (countAfterSwitch_) {
    // A job still running (the lab's own, or a Measure that began before the switch) holds its
    // images until it ends: counted with it, one entry in a few reads tens of MB above the rest.
    // The lab entry is counted once its jobs are done, the same state every time.
    if (host.jobs().busy()) settle(host);
    countAfterSwitch_ = false;
    LabEntry entry{seconds(), 0.0, 0.0, {}, {}, 0, leftState_};
    for (int k = 0; k < int(gl::Kind::Count); ++k) entry.glObjects.push_back(gl::liveObjects(gl::Kind(k)));
    returnFreePages();
    entry.residentMb = residentMb();
    entry.heapMb = heapInUseMb();
    entry.resident = residentParts();
    entry.programs = distinctProgramsLinked();
    entries_[std::string(host.lab().id())].push_back(std::move(entry));
  }
  const double t = seconds();
  if (t - lastFrameAt_ > slowestSeconds_) {
    slowestSeconds_ = t - lastFrameAt_;
    slowestState_ = describeState(host);
  }
  lastFrameAt_ = t;
  if (const double mb = residentMb(); mb > peakMb_) {
    peakMb_ = mb;
    peakSeconds_ = t;
    peakState_ = describeState(host);
  }
  if (t >= nextSample_) {
    nextSample_ = t + sampleSeconds_;
    samples_.push_back({t, residentMb(), gl::liveObjectsTotal(), int(host.jobs().status().size()), frames_, steps_});
  }
}

// The samples, and every lab entry beside them: a step (memory taken once and kept) and a ramp
// (taken again and again) give the same slope over a short run, and only the series tells them
// apart. "" or what could not be written.
std::string SoakDriver::writeRecords(const fs::path& csv, const fs::path& entriesCsv) const {
  std::ostringstream rows;
  rows << "seconds,resident_mb,gl_objects,jobs,frames,steps\n";
  for (auto& x : samples_)
    rows << formatNumber(x.seconds) << "," << formatNumber(x.residentMb) << "," << x.glObjects << "," << x.jobs << ","
         << x.frames << "," << x.steps << "\n";
  std::string written = writeTextFile(csv.string(), rows.str());
  std::vector<std::pair<std::string, const LabEntry*>> byTime;
  for (auto& [lab, entries] : entries_)
    for (auto& e : entries) byTime.emplace_back(lab, &e);
  std::sort(byTime.begin(), byTime.end(), [](auto& a, auto& b) { return a.second->seconds < b.second->seconds; });
  std::ostringstream entryRows;
  entryRows << "seconds,lab,resident_mb,heap_mb,gl_objects,anonymous_mb,file_mb,programs,left\n";
  for (auto& [lab, e] : byTime)
    entryRows << formatNumber(e->seconds) << "," << lab << "," << formatNumber(e->residentMb) << ","
              << formatNumber(e->heapMb) << "," << std::accumulate(e->glObjects.begin(), e->glObjects.end(), 0) << ","
              << formatNumber(e->resident.anonymousMb) << "," << formatNumber(e->resident.fileMb) << "," << e->programs
              << "," << csvField(e->left) << "\n";
  if (written.empty()) written = writeTextFile(entriesCsv.string(), entryRows.str());

  return written;
}

// Memory on lab entries after warm-up (the first fifth of the run): each entry as its growth
// over that lab's first entry after warm-up, and the least-squares slope of those over time.
// False when the slope is judged and missed its goal.
bool SoakDriver::reportMemory(std::ostringstream& s, bool judgeSlope) const {
  bool passed = true;
  const double warm = seconds() * 0.2;
  auto growthSlope = [&](auto mb, size_t& n) {
    std::vector<std::pair<double, double>> growth;
    for (auto& [lab, entries] : entries_) {
      double base = -1.0;
      for (auto& e : entries) {
        if (e.seconds < warm) continue;
        if (base < 0) base = mb(e);
        growth.emplace_back(e.seconds, mb(e) - base);
      }
    }
    n = growth.size();
    return n >= 3 ? leastSquaresSlope(growth) * 600.0 : 0.0;  // MB per 10 minutes
  };
  for (auto& [lab, entries] : entries_) {
    const LabEntry &first = entries.front(), &last = entries.back();
    s << "soak: on entering " << lab << " (" << entries.size() << " times): resident " << formatNumber(first.residentMb)
      << " -> " << formatNumber(last.residentMb) << " MB, heap in use " << formatNumber(first.heapMb) << " -> "
      << formatNumber(last.heapMb) << " MB\n";
  }
  size_t n = 0;
  const double heapSlope = growthSlope([](const LabEntry& e) { return e.heapMb; }, n);
  const double anonymousSlope = growthSlope([](const LabEntry& e) { return e.resident.anonymousMb; }, n);
  const double fileSlope = growthSlope([](const LabEntry& e) { return e.resident.fileMb; }, n);
  const double slope = growthSlope([](const LabEntry& e) { return e.residentMb; }, n);
  if (n >= 3) {
    const bool flat = slope < 1.0;
    s << "soak: on lab entries after warm-up (" << n << "): resident memory slope " << formatNumber(slope)
      << " MB per 10 min"
      << (judgeSlope ? (flat ? " (goal < 1: met)" : " (goal < 1: NOT met)") : " (runs of 10 min or more are judged)")
      << ", heap in use slope " << formatNumber(heapSlope) << " MB per 10 min\n";
    s << "soak: the resident slope in parts: anonymous pages " << formatNumber(anonymousSlope)
      << " MB per 10 min, pages of mapped files (libraries' code) " << formatNumber(fileSlope) << " MB per 10 min\n";
    passed = passed && (flat || !judgeSlope);
    // What the driver keeps per program it meets rises with this count, not with time.
    size_t atWarm = 0, atEnd = 0;
    for (auto& [lab, entries] : entries_)
      for (auto& e : entries) {
        if (e.seconds < warm) atWarm = std::max(atWarm, e.programs);
        atEnd = std::max(atEnd, e.programs);
      }
    s << "soak: distinct programs linked: " << atWarm << " by the end of warm-up, " << atEnd
      << " by the last lab entry\n";
  }
  return passed;
}

// GL objects: every entry into a lab must hold no more than the first did. False where one held more.
bool SoakDriver::reportGlObjects(std::ostringstream& s) const {
  auto total = [](const LabEntry& e) { return std::accumulate(e.glObjects.begin(), e.glObjects.end(), 0); };
  auto kinds = [](const LabEntry& e) {
    std::string d;
    for (size_t k = 0; k < e.glObjects.size(); ++k)
      if (e.glObjects[k])
        d += (d.empty() ? "" : ", ") + std::to_string(e.glObjects[k]) + " " + gl::kindName(gl::Kind(k));
    return d;
  };
  bool passed = true;
  for (auto& [lab, entries] : entries_) {
    const auto [least, most] =
        std::minmax_element(entries.begin(), entries.end(), [&](auto& a, auto& b) { return total(a) < total(b); });
    const bool same = total(*most) <= total(entries.front());
    s << "soak: GL objects on entering " << lab << ": " << entries.size() << " entries, first "
      << total(entries.front()) << ", min " << total(*least) << ", max " << total(*most);
    if (same)
      s << " (back to baseline)\n";
    else
      s << " (ABOVE the first entry: " << kinds(*most) << " against " << kinds(entries.front()) << ")\n";
    passed = passed && same;
  }
  return passed;
}

SoakDriver::Verdict SoakDriver::finish(const fs::path& csv, bool judgeSlope) const {
  std::ostringstream s;
  const fs::path entriesCsv = csv.parent_path() / (csv.stem().string() + "-entries.csv");
  const std::string written = writeRecords(csv, entriesCsv);
  bool passed = written.empty() && nonFiniteFrames_ == 0 && glErrors_ == 0;
  s << "soak: " << formatNumber(seconds() / 60.0) << " min, " << steps_ << " steps (" << labSwitches_
    << " lab switches, " << shaderEdits_ << " shader files broken and fixed, " << meshLoads_ << " meshes loaded, "
    << supersedes_ << " jobs superseded), " << frames_ << " frames\n";
  s << "soak: " << nonFiniteFrames_ << " frames with NaN/Inf, " << glErrors_ << " GL errors\n";

  passed = reportMemory(s, judgeSlope) && passed;
  // The entry furthest above its lab's median heap, and the lab it came from: memory the lab
  // before kept past the switch.
  const LabEntry* outlier = nullptr;
  double above = 0.0;
  std::string outlierLab;
  for (auto& [lab, entries] : entries_) {
    std::vector<double> heap;
    for (auto& e : entries) heap.push_back(e.heapMb);
    std::nth_element(heap.begin(), heap.begin() + std::ptrdiff_t(heap.size() / 2), heap.end());
    for (auto& e : entries)
      if (e.heapMb - heap[heap.size() / 2] > above) {
        above = e.heapMb - heap[heap.size() / 2];
        outlier = &e;
        outlierLab = lab;
      }
  }
  if (outlier)
    s << "soak: the lab entry furthest above its lab's median heap: " << outlierLab << " at "
      << formatNumber(outlier->seconds) << " s, " << formatNumber(above) << " MB above, after " << outlier->left
      << "\n";
  // All samples, whatever state they caught: the range the run went through.
  if (!samples_.empty())
    s << "soak: resident memory over the run " << formatNumber(samples_.front().residentMb) << " -> "
      << formatNumber(samples_.back().residentMb) << " MB\n";
  if (!peakState_.empty())  // every frame is looked at, not only the samples
    s << "soak: the largest resident set after a frame (the peak): " << formatNumber(peakMb_) << " MB at "
      << formatNumber(peakSeconds_) << " s, drawing " << peakState_ << "\n";
  if (!slowestState_.empty())
    s << "soak: the longest step and frame (waits for jobs to end left out): " << formatNumber(slowestSeconds_)
      << " s, ending in " << slowestState_ << "\n";
  passed = reportGlObjects(s) && passed;
  for (auto& p : problems_) s << "soak: problem: " << p << "\n";
  if (!written.empty()) s << "soak: " << written << "\n";
  s << "soak: samples in " << csv.string() << ", lab entries in " << entriesCsv.string() << "; "
    << (passed ? "passed" : "FAILED") << "\n";
  return {s.str(), passed};
}

}  // namespace shadelab
