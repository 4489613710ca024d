// The surface lab's own copies of the scene's meshes: subdivided to a level (displacement, the
// truth), with tangent frames from the sources the configuration compares, and the world size of a
// UV unit per vertex. Built only when asked, kept for the last few keys, so switching between a
// technique and the truth does not subdivide again.
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "app/scene/gpu_mesh.h"
#include "app/scene/scene.h"

namespace shadelab {

enum class TangentSource { Generated, Mesh, Screen, Count };

struct SurfaceDraw {
  GpuMesh mesh;
  glm::mat4 model{1.0f};
  int material = 0;
  bool hasUvs = false;
  size_t triangles = 0;
  float meanEdge = 0.0f;  // model space, for sizing the frame overlay
};

struct SurfaceGeometryKey {
  int revision = -1;  // the scene build
  int level = 0;      // midpoint subdivisions
  int parts = 1;      // then every edge cut into this many (tessellation where there are no tessellation stages)
  bool tangents = false;
  TangentSource source = TangentSource::Generated, compare = TangentSource::Generated;
  bool operator==(const SurfaceGeometryKey&) const = default;
};

class SurfaceGeometry {
 public:
  // The meshes for `key`, built now if not kept. `notes` gets what the student should know (a mesh
  // with no tangents of its own, degenerate UVs).
  const std::vector<SurfaceDraw>& get(const Scene& scene, const SurfaceGeometryKey& key,
                                      std::vector<std::string>& notes);
  void clear() { kept_.clear(); }

 private:
  struct Entry {
    SurfaceGeometryKey key;
    std::vector<SurfaceDraw> draws;
    std::vector<std::string> notes;
  };
  std::deque<Entry> kept_;  // most recent first
};

}  // namespace shadelab
