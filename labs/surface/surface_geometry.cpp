#include "labs/surface/surface_geometry.h"

#include <algorithm>
#include <deque>
#include <memory>
#include <mutex>

#include "app/lab/host_batch.h"
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

// What the CPU makes of one of the scene's meshes for a key: subdivided, its tangent frames chosen,
// each vertex's UV scale. The work of a host's first frame at a level (a wall subdivided to a
// vertex per texel is half a million triangles), and the same for every host a process makes of
// one scene: a grading child draws the solution, each listed mistake and each slip with a host of
// its own. So while a HostBatch is open the last few are kept, found by comparing the source mesh
// whole; outside one (a window) the lab's work goes when the lab is left.
struct PreparedMesh {
  MeshData source;
  SurfaceGeometryKey key;  // its revision aside: another host's build of the same scene matches
  MeshData mesh;
  std::vector<float> uScale, vScale, compare;
  float meanEdge = 0.0f;
  std::vector<std::string> notes;
};

bool sameMesh(const MeshData& a, const MeshData& b) {
  return a.name == b.name && a.material == b.material && a.positions == b.positions && a.normals == b.normals &&
         a.uvs == b.uvs && a.tangents == b.tangents && a.sourceTangents == b.sourceTangents && a.indices == b.indices;
}

std::shared_ptr<const PreparedMesh> prepare(const MeshData& source, const SurfaceGeometryKey& key) {
  auto out = std::make_shared<PreparedMesh>();
  out->source = source;
  out->key = key;
  MeshData m = source;
  const bool uvs = !m.uvs.empty();
  if (key.tangents && uvs) {
    const TangentReport r = computeTangents(m);  // may split vertices where mirrored UVs meet
    if (r.degenerateUvTriangles)
      out->notes.push_back("mesh '" + m.name + "': " + std::to_string(r.degenerateUvTriangles) +
                           " triangles have degenerate UVs (zero area in texture space) and add nothing to the " +
                           "tangents; " + std::to_string(r.fallbacks) +
                           " vertices touch only such triangles and get an arbitrary frame");
    const bool wantsOwn = key.source == TangentSource::Mesh || key.compare == TangentSource::Mesh;
    if (wantsOwn && m.sourceTangents.size() != m.positions.size())
      out->notes.push_back("mesh '" + m.name + "' has no tangents of its own (glTF TANGENT): generated ones stand in");
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
  out->compare = flatten(compare);
  out->meanEdge = float(meanEdgeLength(m.positions, m.indices));
  for (auto& s : uvScale(m)) {
    out->uScale.push_back(s.x);
    out->vScale.push_back(s.y);
  }
  out->mesh = std::move(m);
  return out;
}

// The meshes an open batch keeps, most recent first: a level and the truth's, of a scene or two.
class KeptMeshes {
 public:
  KeptMeshes() {
    HostBatch::onClose([this] {
      const std::lock_guard<std::mutex> held(lock_);
      list_.clear();
    });
  }

  std::shared_ptr<const PreparedMesh> find(const MeshData& source, const SurfaceGeometryKey& key) {
    const std::lock_guard<std::mutex> held(lock_);
    for (auto it = list_.begin(); it != list_.end(); ++it)
      if ((*it)->key == key && sameMesh((*it)->source, source)) {
        std::shared_ptr<const PreparedMesh> found = *it;
        list_.erase(it);
        list_.push_front(found);
        return found;
      }
    return nullptr;
  }

  void keep(std::shared_ptr<const PreparedMesh> made) {
    const std::lock_guard<std::mutex> held(lock_);
    list_.push_front(std::move(made));
    while (list_.size() > 3) list_.pop_back();
  }

 private:
  std::mutex lock_;
  std::deque<std::shared_ptr<const PreparedMesh>> list_;
};

std::shared_ptr<const PreparedMesh> prepared(const MeshData& source, SurfaceGeometryKey key) {
  static KeptMeshes kept;
  key.revision = -1;
  if (!HostBatch::open()) return prepare(source, key);
  if (auto found = kept.find(source, key)) return found;
  std::shared_ptr<const PreparedMesh> made = prepare(source, key);
  kept.keep(made);
  return made;
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
    const std::shared_ptr<const PreparedMesh> m = prepared(scene.meshes[size_t(inst.mesh)], key);
    SurfaceDraw d;
    d.model = inst.model;
    d.material = m->mesh.material;
    d.hasUvs = !m->mesh.uvs.empty();
    d.triangles = m->mesh.triangleCount();
    d.meanEdge = m->meanEdge;
    d.mesh = GpuMesh::upload(m->mesh);
    d.mesh.setScalars(kScalar0, m->uScale);
    d.mesh.setScalars(kScalar1, m->vScale);
    d.mesh.setAttribute(kVector0, 4, m->compare);
    addNotes(e.notes, m->notes);
    e.draws.push_back(std::move(d));
  }
  addNotes(notes, e.notes);
  kept_.push_front(std::move(e));
  while (kept_.size() > 3) kept_.pop_back();
  return kept_.front().draws;
}

}  // namespace shadelab
