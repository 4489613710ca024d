// Every lab, listed by hand: static self-registration is silently dropped by linkers when a
// lab's object file is otherwise unreferenced.
#include "labs/lab.h"
#include "labs/denoise/denoise_lab.h"
#include "labs/filtering/filtering_lab.h"
#include "labs/shading/shading_lab.h"
#include "labs/shadows/shadows_lab.h"
#include "labs/surface/surface_lab.h"

namespace shadelab {

std::vector<std::string> labIds() { return {"shading", "shadows", "surface", "denoise", "filtering"}; }

std::unique_ptr<Lab> makeLab(std::string_view id) {
  if (id == "shading") return std::make_unique<ShadingLab>();
  if (id == "shadows") return std::make_unique<ShadowsLab>();
  if (id == "surface") return std::make_unique<SurfaceLab>();
  if (id == "denoise") return std::make_unique<DenoiseLab>();
  if (id == "filtering") return std::make_unique<FilteringLab>();
  return nullptr;
}

}  // namespace shadelab
