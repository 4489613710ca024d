// RayScene where there is no Embree (the browser): the BVH the GPU tracer walks, traversed on the
// CPU. The same triangles and the same rays, so the same truth, only slower.
#include "app/measure/bvh.h"
#include "labs/shadows/gpu_tracer.h"
#include "labs/shadows/ray_visibility.h"

namespace shadelab {

struct RayScene::Impl {
  Bvh bvh;
};

RayScene::RayScene(const Scene& s) : impl_(std::make_unique<Impl>(Impl{Bvh(sceneTriangles(s))})) {
  triangles_ = impl_->bvh.triangles().size();
}

RayScene::~RayScene() = default;

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float maxDistance) const {
  return impl_->bvh.anyHit(o, d, 0.0f, maxDistance);
}

}  // namespace shadelab
