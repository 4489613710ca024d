#include "labs/shading/shading_lab.h"

#include <cmath>
#include <set>

#include <glm/gtc/matrix_inverse.hpp>

#include "app/lab/technique.h"
#include "app/lab/variants.h"
#include "app/shader/preprocessor.h"

namespace shadelab {
namespace {

// Where the lighting is evaluated: a new mode is its row here, its branch in shade.vert/.frag and its test.
struct ShadingModeRow {
  ShadingMode value;
  std::string_view name;
  std::string_view define;
  // One lighting per triangle: a geometry shader, or unwelded faces, gives its normal to its three corners.
  bool perFace;
};
constexpr ShadingModeRow kShadingModes[] = {
    {ShadingMode::Flat, "flat", "MODE_FLAT", true},
    {ShadingMode::Gouraud, "gouraud", "MODE_GOURAUD", false},
    {ShadingMode::Phong, "phong", "MODE_PHONG", false},
};
static_assert(coversEnum<ShadingMode>(kShadingModes));
constexpr Named<SpecularModel> kSpecularNames[] = {{SpecularModel::BlinnPhong, "blinn-phong"},
                                                   {SpecularModel::Phong, "phong"}};
static_assert(coversEnum<SpecularModel>(kSpecularNames));
constexpr Named<UvInterpolation> kUvNames[] = {{UvInterpolation::Perspective, "perspective"},
                                               {UvInterpolation::Affine, "affine"},
                                               {UvInterpolation::ByHand, "by-hand"}};
static_assert(coversEnum<UvInterpolation>(kUvNames));
constexpr Named<FlatFaces> kFlatFacesNames[] = {{FlatFaces::GeometryShader, "geometry_shader"},
                                                {FlatFaces::Unwelded, "unwelded"}};
static_assert(coversEnum<FlatFaces>(kFlatFacesNames));

// Flat mode drawn from unwelded faces: asked for, or where there are no geometry shaders (WebGL2).
bool drawsUnwelded(const ShadingParams& p) {
  return rowOf(kShadingModes, p.mode).perFace &&
         (p.flatFaces == FlatFaces::Unwelded || glslDialect() == GlslDialect::Es300);
}

// Flat shading without a geometry shader: every triangle gets three vertices of its own, each
// carrying what flat.geom computes from the whole triangle: the face's normal (the cross product
// turned to agree with the vertex normals; their average where the face has no area) in the
// normal, and the face's centroid in kVector0, where the vertex stage lights it. Three times the
// vertices, and all three corners compute the same colour.
GpuMesh unweldedFaces(const MeshData& m) {
  MeshData out;
  std::vector<float> centroids;
  const size_t corners = m.indices.size() / 3 * 3;
  out.positions.reserve(corners);
  out.normals.reserve(corners);
  if (!m.uvs.empty()) out.uvs.reserve(corners);
  centroids.reserve(corners * 4);
  for (size_t t = 0; t < corners; t += 3) {
    const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
    const glm::vec3 p[3] = {m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]};
    glm::vec3 averaged(0.0f);
    if (!m.normals.empty()) averaged = m.normals[i[0]] + m.normals[i[1]] + m.normals[i[2]];
    const glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
    glm::vec3 n = glm::dot(face, face) > 0.0f           ? glm::normalize(face)
                  : glm::dot(averaged, averaged) > 0.0f ? glm::normalize(averaged)
                                                        : glm::vec3(0, 1, 0);
    if (glm::dot(n, averaged) < 0.0f) n = -n;  // the winding disagrees with the normals: trust the normals
    const glm::vec3 centre = (p[0] + p[1] + p[2]) / 3.0f;
    for (int k = 0; k < 3; ++k) {
      out.positions.push_back(p[k]);
      out.normals.push_back(n);
      if (!m.uvs.empty()) out.uvs.push_back(m.uvs[i[k]]);
      centroids.insert(centroids.end(), {centre.x, centre.y, centre.z, 1.0f});
    }
  }
  out.indices.resize(corners);
  for (size_t k = 0; k < corners; ++k) out.indices[k] = uint32_t(k);
  GpuMesh mesh = GpuMesh::upload(out);
  mesh.setAttribute(kVector0, 4, centroids);
  return mesh;
}

// Light k sits on a ring around the scene at the chosen elevation, with its own colour, so
// several highlights are told apart.
const glm::vec3 kLightColor[4] = {{1.0f, 0.95f, 0.9f}, {0.6f, 0.75f, 1.0f}, {1.0f, 0.7f, 0.5f}, {0.8f, 1.0f, 0.8f}};
const float kLightAzimuthDeg[4] = {35.0f, 215.0f, 125.0f, 305.0f};

}  // namespace

std::string_view ShadingLab::summary() const {
  return "Where lighting is evaluated changes what you see. Flat shading lights each triangle once, "
         "Gouraud lights each vertex and blends colours, Phong lights each pixel with an interpolated normal. "
         "Blinn-Phong and Phong differ in the highlight lobe. The checker floor is two triangles: "
         "switch uv_interpolation to affine to see why GPUs divide by w.";
}

void ShadingLab::visitParams(ParamVisitor& v) {
  auto& p = params;
  v.section("Shading");
  v.enumParam({"mode", "Shading frequency", "",
               "flat: once per triangle (face normal); gouraud: per vertex, "
               "colours interpolated; phong: per fragment, normals interpolated."},
              p.mode, namesOf<kShadingModes>());
  v.enumParam({"specular", "Specular model", "",
               "blinn-phong: (N.H)^p with the half vector; phong: (R.V)^p "
               "with the reflected light. Blinn-Phong needs ~4x the exponent for the same highlight."},
              p.specular, namesOf<kSpecularNames>());
  v.enumParam({"uv_interpolation", "UV interpolation", "",
               "perspective: correct (divide by w); affine: "
               "linear in screen space (noperspective), bends the checker on large triangles; by-hand: perspective-"
               "correct from screen-linear inputs, written in shading/perspective_correct.glsl (an exercise). "
               "WebGL2 has no noperspective: screen-linear values travel as (v w, w) there."},
              p.uvInterpolation, namesOf<kUvNames>());
  if (p.mode != ShadingMode::Flat)
    v.unavailable("only for mode flat");
  else if (glslDialect() == GlslDialect::Es300)
    v.unavailable("WebGL2 has no geometry shaders: faces are always unwelded");
  v.enumParam({"flat_faces", "Flat faces from", "",
               "How flat mode gives a triangle one normal and one colour. "
               "geometry_shader: a geometry shader sees the whole triangle, lights it once at its centroid and hands "
               "the colour to its three corners. unwelded: no vertex is shared (three per triangle, each carrying its "
               "face's normal and centroid) and the vertex stage lights it: the way without geometry shaders "
               "(WebGL2), at three times the vertices. The two draw the same picture."},
              p.flatFaces, namesOf<kFlatFacesNames>());
  v.intParam({"tessellation", "Tessellation", "segments",
              "Segments around the procedural spheres and tori "
              "(rings = half). Files are drawn as loaded."},
             p.tessellation, 3, kReferenceTessellation);
  v.section("Material");
  v.floatParam({"ka", "Ambient ka", "", "Ambient reflectance: the constant term that stands in for indirect light."},
               p.ka, 0.0f, 1.0f);
  v.floatParam({"kd", "Diffuse kd", "", "Diffuse (Lambertian) reflectance."}, p.kd, 0.0f, 1.0f);
  v.floatParam({"ks", "Specular ks", "", "Specular reflectance."}, p.ks, 0.0f, 1.0f);
  v.floatParam({"shininess", "Shininess p", "", "Specular exponent: larger = smaller, sharper highlight."}, p.shininess,
               1.0f, 1024.0f, true);
  v.boolParam({"textures", "Textures", "", "Use base-colour textures. Off: no image is decoded or uploaded."},
              p.textures);
  v.section("Lights");
  v.intParam({"lights", "Point lights", "", "Number of point lights (0 = ambient only). A compile-time loop bound."},
             p.lights, 0, 4);
  v.floatParam({"light_power", "Light power", "",
                "Each light's irradiance at the scene centre; lights sit three scene "
                "radii away and fall off as 1/r^2."},
               p.lightPower, 0.0f, 1e5f, true);
  v.floatParam({"light_elevation", "Light elevation", "deg",
                "Height of the lights above the horizon. Near 0 the "
                "light grazes the floor: N.L -> 0."},
               p.lightElevationDeg, -10.0f, 90.0f);
}

SceneNeeds ShadingLab::needs() const {
  SceneNeeds n;
  n.uvs = params.textures;
  n.baseColorTextures = params.textures;
  n.tessellation = params.tessellation;
  return n;
}

ProgramSpec ShadingLab::programSpec(const ShadingParams& p, bool textured) const {
  ProgramSpec spec;
  const ShadingModeRow& mode = rowOf(kShadingModes, p.mode);
  spec.name = "shading/" + std::string(mode.name) + (textured ? "+texture" : "");
  spec.stages.push_back({GL_VERTEX_SHADER, "shading/shade.vert"});
  const bool unwelded = drawsUnwelded(p);
  if (mode.perFace && !unwelded) spec.stages.push_back({GL_GEOMETRY_SHADER, "shading/flat.geom"});
  spec.stages.push_back({GL_FRAGMENT_SHADER, "shading/shade.frag"});
  spec.defines.emplace_back(mode.define, "1");
  if (unwelded) {
    spec.name += "+unwelded";
    spec.defines.emplace_back("FLAT_UNWELDED", "1");
  }
  spec.defines.emplace_back("NUM_LIGHTS", std::to_string(p.lights));
  if (p.specular == SpecularModel::Phong) spec.defines.emplace_back("SPECULAR_PHONG", "1");
  if (p.uvInterpolation == UvInterpolation::Affine) spec.defines.emplace_back("AFFINE_UV", "1");
  if (p.uvInterpolation == UvInterpolation::ByHand) spec.defines.emplace_back("UV_BY_HAND", "1");
  if (textured) spec.defines.emplace_back("BASE_COLOR_MAP", "1");
  return spec;
}

// Per shading mode, a pairwise cover of the other choices the shaders are compiled for: every value,
// and every pair of values, of specular model, UV interpolation, textures, light count and (flat
// mode) the faces' source in some program of that mode (gl/lab_lifecycle_test.cpp draws random
// settings against it).
std::vector<ProgramSpec> ShadingLab::allPrograms() const {
  std::vector<ProgramSpec> all;
  for (int mode = 0; mode < int(ShadingMode::Count); ++mode) {
    const int faces = ShadingMode(mode) == ShadingMode::Flat ? 2 : 1;
    for (const auto& row : pairwiseCover({2, int(std::size(kUvNames)), 2, 5, faces})) {
      ShadingParams p;
      p.mode = ShadingMode(mode);
      p.specular = SpecularModel(row[0]);
      p.uvInterpolation = UvInterpolation(row[1]);
      p.lights = row[3];
      p.flatFaces = FlatFaces(row[4]);
      all.push_back(programSpec(p, row[2] == 1));
    }
  }
  // One of each: rows that differ only in what the program ignores compile the same program.
  std::set<std::string> seen;
  std::erase_if(all, [&](const ProgramSpec& spec) { return !seen.insert(spec.key()).second; });
  return all;
}

std::string ShadingLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  return {};
}

void ShadingLab::render(Frame& frame) {
  auto pass = frame.pass("shade");
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // open meshes (the teapot) show their inside
  // Alpha 0 marks background: metrics use it to tell surface error from silhouette error.
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  const glm::mat4 viewProj = frame.viewProj();
  const Bounds bounds = frame.scene.bounds;
  const float radius = bounds.radius();
  glm::vec3 lightPos[4], lightPower[4];
  const float elevation = glm::radians(params.lightElevationDeg);
  for (int k = 0; k < 4; ++k) {
    const float az = glm::radians(kLightAzimuthDeg[k]);
    const glm::vec3 dir(std::cos(elevation) * std::sin(az), std::sin(elevation), std::cos(elevation) * std::cos(az));
    // Three scene radii out, with the intensity that gives irradiance `light_power` at the centre:
    // falloff across the scene stays visible without any surface sitting next to a light.
    const float distance = 3.0f * radius;
    lightPos[k] = bounds.center() + dir * distance;
    lightPower[k] = kLightColor[k] * params.lightPower * distance * distance;
  }

  // Built when flat mode first needs them, then kept for the scene build (a measurement's Phong
  // frames between flat ones do not rebuild them); they go with the lab.
  const bool unwelded = drawsUnwelded(params);
  if (unwelded && unweldedRevision_ != frame.scene.revision) {
    unwelded_.clear();
    for (auto& m : frame.scene.meshes) unwelded_.push_back(unweldedFaces(m));
    unweldedRevision_ = frame.scene.revision;
  }

  for (size_t i : frame.scene.nearestFirst(frame.camera.eye())) {
    const Instance& inst = frame.scene.instances[i];
    const Material& mat = frame.scene.materials[size_t(frame.scene.meshes[size_t(inst.mesh)].material)];
    const gl::Texture2D* tex = params.textures ? frame.gpu.baseColorTexture(mat) : nullptr;
    Program& prog = programs_[tex != nullptr].get(*shaders_, programSpec(params, tex != nullptr));
    prog.use();
    prog.set("u_model", inst.model);
    prog.set("u_viewProj", viewProj);
    prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(inst.model)));
    prog.set("u_eye", frame.camera.eye());
    prog.setArray("u_lightPos", lightPos, 4);
    prog.setArray("u_lightPower", lightPower, 4);
    prog.set("u_ambient", glm::vec3(1.0f));
    prog.set("u_ka", params.ka);
    prog.set("u_kd", params.kd);
    prog.set("u_ks", params.ks);
    prog.set("u_shininess", params.shininess);
    const float minDistance = std::max(1e-3f * radius, 1e-15f);
    prog.set("u_minDistance2", minDistance * minDistance);
    prog.set("u_baseColor", mat.baseColor);
    if (tex) {
      tex->bind(0);
      prog.set("u_baseColorMap", 0);
    }
    if (unwelded)
      unwelded_[size_t(inst.mesh)].draw();
    else
      frame.gpu.draw(inst);
  }
}

std::vector<ProgramRef> ShadingLab::activePrograms() const { return heldPrograms(programs_); }

std::vector<std::string> ShadingLab::warnings() const {
  std::vector<std::string> w;
  if (params.lights == 0) w.push_back("no lights: only the ambient term ka is drawn");
  if (params.lights > 0 && params.lightElevationDeg < 2.0f)
    w.push_back("grazing light (elevation " + formatNumber(params.lightElevationDeg) +
                " deg): N.L is near 0 on the floor, so it is lit by the ambient term alone");
  if (params.mode == ShadingMode::Gouraud && params.shininess > 100.0f && params.tessellation < 64)
    w.push_back("Gouraud with shininess " + formatNumber(params.shininess) +
                ": highlights narrower than a triangle fall between vertices and are lost");
  if (params.lightPower > 20.0f) w.push_back("light power above 20: most lit pixels saturate to white");
  return w;
}

ReferenceSpec ShadingLab::reference() const {
  ReferenceSpec spec;
  spec.kind = TruthKind::Image;
  spec.truth = "Phong at 256 segments";
  spec.description =
      "per-fragment Phong shading on the 256-segment tessellation with perspective-correct UVs, at the "
      "same resolution (one sample per pixel: the error is shading and geometry, not aliasing)";
  spec.overrides = edits<ShadingLab>(params, [](ShadingParams& p) {
    p.mode = ShadingMode::Phong;
    p.uvInterpolation = UvInterpolation::Perspective;
    p.tessellation = kReferenceTessellation;
  });
  spec.cheap = true;  // one frame, and the host keeps its scene build for the next measurement
  return spec;
}

std::vector<StressCase> ShadingLab::stressCases() const {
  const auto edit = [](auto change) { return fromDefaults<ShadingLab>(change); };
  return {
      {"grazing-light", edit([](ShadingParams& p) { p.lightElevationDeg = 0.1f; }), "", "", "grazing light"},
      {"light-below-horizon", edit([](ShadingParams& p) { p.lightElevationDeg = -10.0f; }), "", "", ""},
      {"flat-degenerate-poles", edit([](ShadingParams& p) { p.mode = ShadingMode::Flat, p.tessellation = 3; }),
       "sphere", "", ""},
      {"gouraud-sharp-highlight",
       edit([](ShadingParams& p) { p.mode = ShadingMode::Gouraud, p.shininess = 1024.0f, p.ks = 1.0f; }), "", "",
       "highlights narrower"},
      {"shininess-1", edit([](ShadingParams& p) { p.shininess = 1.0f, p.ks = 1.0f; }), "", "", ""},
      {"no-lights", edit([](ShadingParams& p) { p.lights = 0; }), "", "", "no lights"},
      {"huge-power", edit([](ShadingParams& p) { p.lightPower = 100000.0f, p.lights = 4; }), "", "", "saturate"},
      {"affine-grazing-camera", edit([](ShadingParams& p) { p.uvInterpolation = UvInterpolation::Affine; }),
       "checker-plane", "pitch=0.5", ""},
      {"extreme-depth-range", {}, "", "near=0.000001,far=1000000", ""},
      {"camera-inside-sphere", {}, "sphere", "distance=0.5", ""},
  };
}

std::vector<SweepAxis> ShadingLab::standardSweep() const {
  return {{"mode", {"flat", "gouraud", "phong"}}, {"tessellation", {"8", "16", "32", "64", "128"}}};
}

}  // namespace shadelab
