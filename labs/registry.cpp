// Every lab, listed once. A new lab is one row here; the app, the CLI, the soak and the tests all
// take their list of labs from this table.
#include "app/lab/lab.h"
#include "labs/denoise/denoise_lab.h"
#include "labs/filtering/filtering_lab.h"
#include "labs/minimal/minimal_lab.h"
#include "labs/shading/shading_lab.h"
#include "labs/shadows/shadows_lab.h"
#include "labs/surface/surface_lab.h"

namespace shadelab {
namespace {

template <typename L>
std::unique_ptr<Lab> make() {
  return std::make_unique<L>();
}

constexpr LabEntry kLabs[] = {
    {"shading", make<ShadingLab>},     {"shadows", make<ShadowsLab>},
    {"surface", make<SurfaceLab>},     {"denoise", make<DenoiseLab>},
    {"filtering", make<FilteringLab>}, {"minimal", make<MinimalLab>, false},  // the skeleton labs/README.md starts from
};

}  // namespace

std::span<const LabEntry> labRegistry() { return kLabs; }

std::vector<std::string> labIds() {
  std::vector<std::string> ids;
  for (const LabEntry& entry : kLabs) ids.emplace_back(entry.id);
  return ids;
}

std::vector<std::string> menuLabIds() {
  std::vector<std::string> ids;
  for (const LabEntry& entry : kLabs)
    if (entry.inMenu) ids.emplace_back(entry.id);
  return ids;
}

std::unique_ptr<Lab> makeLab(std::string_view id) {
  for (const LabEntry& entry : kLabs)
    if (entry.id == id) return entry.make();
  return nullptr;
}

}  // namespace shadelab
