// RayScene on the desktop: Intel Embree traces the shadow rays.
#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>

#include "labs/shadows/ray_visibility.h"

namespace shadelab {

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

RayScene::RayScene(const Scene& s) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice("threads=1");
  impl_->scene = rtcNewScene(impl_->device);
  for (const Instance& inst : s.instances) {
    const MeshData& m = s.meshes[size_t(inst.mesh)];
    if (m.indices.empty()) continue;
    RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m.positions.size()));
    for (size_t i = 0; i < m.positions.size(); ++i) {
      const glm::vec3 p = glm::vec3(inst.model * glm::vec4(m.positions[i], 1.0f));
      v[3 * i] = p.x;
      v[3 * i + 1] = p.y;
      v[3 * i + 2] = p.z;
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), m.triangleCount()));
    std::copy(m.indices.begin(), m.indices.end(), idx);
    rtcCommitGeometry(g);
    rtcAttachGeometry(impl_->scene, g);
    rtcReleaseGeometry(g);
    triangles_ += m.triangleCount();
  }
  rtcCommitScene(impl_->scene);
}

RayScene::~RayScene() {
  rtcReleaseScene(impl_->scene);
  rtcReleaseDevice(impl_->device);
}

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float maxDistance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = o.x;
  ray.org_y = o.y;
  ray.org_z = o.z;
  ray.dir_x = d.x;
  ray.dir_y = d.y;
  ray.dir_z = d.z;
  ray.tnear = 0.0f;
  ray.tfar = maxDistance;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace shadelab
