#include "app/lab/lab.h"

namespace shadelab {

Metrics Judge::metrics(const ImageF& image, const ImageF& reference) const {
  const ImageError e = compareImages(image, reference);
  return {{"rmse", e.rmse},
          {"surface_rmse", e.coveredRmse},
          {"max_error", e.maxError},
          {"mean_error", e.meanError},
          {"bad_pixel_pct", e.badPixelPct}};
}

ReferenceSpec referenceOf(const Lab& lab) {
  const Judge* judge = lab.judge();
  return judge ? judge->reference() : ReferenceSpec{};
}

std::vector<StressCase> stressCasesOf(const Lab& lab) {
  const Judge* judge = lab.judge();
  return judge ? judge->stressCases() : std::vector<StressCase>{};
}

}  // namespace shadelab
