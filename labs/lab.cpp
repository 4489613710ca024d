#include "labs/lab.h"

namespace shadelab {

Metrics Lab::metrics(const ImageF& image, const ImageF& reference) const {
  const ImageError e = compareImages(image, reference);
  return {{"rmse", e.rmse}, {"surface_rmse", e.coveredRmse}, {"max_error", e.maxError},
          {"mean_error", e.meanError}, {"bad_pixel_pct", e.badPixelPct}};
}

}  // namespace shadelab
