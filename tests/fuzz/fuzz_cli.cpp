// The command line: the input is argv (arguments separated by NUL bytes). It is parsed as the
// binary parses it; then each --set is applied to a fresh lab and --camera is parsed, which is
// what a session does with them before drawing.
#include <string>
#include <vector>

#include "app/cli/options.h"
#include "app/lab/lab.h"
#include "app/scene/camera.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args{"shadelab"};
  std::string_view rest = shadelab::fuzz::asText(data, size);
  while (!rest.empty() && args.size() < 64) {
    const auto [arg, tail] = shadelab::fuzz::splitAt(rest, std::string_view("\0", 1));
    args.emplace_back(arg);
    if (tail.data() == nullptr || tail.empty()) break;
    rest = tail;
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  shadelab::Options options;
  if (!shadelab::parseOptions(int(args.size()), argv.data(), options).empty()) return 0;
  auto lab = shadelab::makeLab(options.lab.empty() ? "shading" : options.lab);
  if (!lab) return 0;
  for (auto& assignment : options.sets) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos) continue;
    std::string key = assignment.substr(0, eq);
    if (key.rfind(std::string(lab->id()) + ".", 0) == 0) key = key.substr(lab->id().size() + 1);
    shadelab::SetFromString set(lab->id(), key, assignment.substr(eq + 1));
    lab->visitParams(set);
    (void)set.result();
  }
  shadelab::OrbitCamera camera;
  (void)camera.parse(options.camera);
  return 0;
}
