#include "labs/surface/surface_geometry.h"

#include <algorithm>

#include "app/scene/mesh_topology.h"
#include "labs/surface/subdivide.h"

namespace shadelab {
namespace {

std::vector<float> flatten(const std::vector<glm::vec4>& v) {
  std::vector<float> out;
  out.reserve(v.size() * 4);
  for (auto& x : v) out.insert(out.end(), {x.x, x.y, x.z, x.w});
  return out;
}

// Two draws of one frame (the surface and the overlay) may share an entry: say each thing once.
void addNotes(std::vector<std::string>& to, const std::vector<std::string>& from) {
  for (const std::string& n : from)
    if (std::find(to.begin(), to.end(), n) == to.end()) to.push_back(n);
}

}  // namespace

const std::vector<SurfaceDraw>& SurfaceGeometry::get(const Scene& scene, const SurfaceGeometryKey& key,
                                                     std::vector<std::string>& notes) {
  for (auto it = kept_.begin(); it != kept_.end(); ++it)
    if (it->key == key) {
      if (it != kept_.begin()) {
        Entry e = std::move(*it);
        kept_.erase(it);
        kept_.push_front(std::move(e));
      }
      addNotes(notes, kept_.front().notes);
      return kept_.front().draws;
    }
  Entry e;
  e.key = key;
  for (const Instance& inst : scene.instances) {
    MeshData m = scene.meshes[size_t(inst.mesh)];
    const bool uvs = !m.uvs.empty();
    if (key.tangents && uvs) {
      const TangentReport r = computeTangents(m);  // may split vertices where mirrored UVs meet
      if (r.degenerateUvTriangles)
        e.notes.push_back(
            "mesh '" + m.name + "': " + std::to_string(r.degenerateUvTriangles) +
            " triangles have degenerate UVs (zero area in texture space) and add nothing to the tangents; " +
            std::to_string(r.fallbacks) + " vertices touch only such triangles and get an arbitrary frame");
      const bool wantsOwn = key.source == TangentSource::Mesh || key.compare == TangentSource::Mesh;
      if (wantsOwn && m.sourceTangents.size() != m.positions.size())
        e.notes.push_back("mesh '" + m.name + "' has no tangents of its own (glTF TANGENT): generated ones stand in");
    }
    m = splitEdges(subdivide(m, key.level), uvs ? key.parts : 1);  // without UVs nothing is displaced
    const std::vector<glm::vec4> own = m.sourceTangents.size() == m.positions.size() ? m.sourceTangents : m.tangents;
    const std::vector<glm::vec4>& generated = m.tangents;
    auto frames = [&](TangentSource s) -> const std::vector<glm::vec4>& {
      return s == TangentSource::Mesh ? own : generated;
    };
    std::vector<glm::vec4> compare = key.tangents && uvs ? frames(key.compare) : std::vector<glm::vec4>();
    if (key.tangents && uvs) m.tangents = frames(key.source);
    if (m.tangents.empty()) m.tangents.assign(m.positions.size(), glm::vec4(1, 0, 0, 1));  // unused, but bound
    if (compare.empty()) compare = m.tangents;
    SurfaceDraw d;
    d.model = inst.model;
    d.material = m.material;
    d.hasUvs = uvs;
    d.triangles = m.triangleCount();
    d.meanEdge = float(meanEdgeLength(m.positions, m.indices));
    d.mesh = GpuMesh::upload(m);
    std::vector<float> su, sv;
    for (auto& s : uvScale(m)) {
      su.push_back(s.x);
      sv.push_back(s.y);
    }
    d.mesh.setScalars(kScalar0, su);
    d.mesh.setScalars(kScalar1, sv);
    d.mesh.setAttribute(kVector0, 4, flatten(compare));
    e.draws.push_back(std::move(d));
  }
  addNotes(notes, e.notes);
  kept_.push_front(std::move(e));
  while (kept_.size() > 3) kept_.pop_back();
  return kept_.front().draws;
}

}  // namespace shadelab
