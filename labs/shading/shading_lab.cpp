#include "labs/shading/shading_lab.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "lab/technique.h"
#include "shader/preprocessor.h"

namespace shadelab {
namespace {

// Where the lighting is evaluated: a new mode is its row here, its branch in shade.vert/.frag and its test.
struct ShadingModeRow {
  ShadingMode value;
  std::string_view name;
  std::string_view define;
  bool perFace;  // a geometry shader hands each triangle's normal to its three corners
};
constexpr ShadingModeRow kShadingModes[] = {
    {ShadingMode::Flat, "flat", "MODE_FLAT", true},
    {ShadingMode::Gouraud, "gouraud", "MODE_GOURAUD", false},
    {ShadingMode::Phong, "phong", "MODE_PHONG", false},
};
static_assert(coversEnum<ShadingMode>(kShadingModes));
constexpr std::string_view kSpecularNames[] = {"blinn-phong", "phong"};
constexpr std::string_view kUvNames[] = {"perspective", "affine"};

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
  v.enumParam({"mode", "Shading frequency", "", "flat: once per triangle (face normal); gouraud: per vertex, "
               "colours interpolated; phong: per fragment, normals interpolated."}, p.mode, namesOf<kShadingModes>());
  v.enumParam({"specular", "Specular model", "", "blinn-phong: (N.H)^p with the half vector; phong: (R.V)^p "
               "with the reflected light. Blinn-Phong needs ~4x the exponent for the same highlight."}, p.specular, kSpecularNames);
  if (glslDialect() == GlslDialect::Es300) v.unavailable("GLSL ES 3.00 (WebGL2) has no noperspective: UVs are perspective-correct");
  v.enumParam({"uv_interpolation", "UV interpolation", "", "perspective: correct (divide by w); affine: "
               "linear in screen space (noperspective), bends the checker on large triangles."}, p.uvInterpolation, kUvNames);
  v.intParam({"tessellation", "Tessellation", "segments", "Segments around the procedural spheres and tori "
              "(rings = half). Files are drawn as loaded."}, p.tessellation, 3, kReferenceTessellation);
  v.section("Material");
  v.floatParam({"ka", "Ambient ka", "", "Ambient reflectance: the constant term that stands in for indirect light."}, p.ka, 0.0f, 1.0f);
  v.floatParam({"kd", "Diffuse kd", "", "Diffuse (Lambertian) reflectance."}, p.kd, 0.0f, 1.0f);
  v.floatParam({"ks", "Specular ks", "", "Specular reflectance."}, p.ks, 0.0f, 1.0f);
  v.floatParam({"shininess", "Shininess p", "", "Specular exponent: larger = smaller, sharper highlight."}, p.shininess, 1.0f, 1024.0f, true);
  v.boolParam({"textures", "Textures", "", "Use base-colour textures. Off: no image is decoded or uploaded."}, p.textures);
  v.section("Lights");
  v.intParam({"lights", "Point lights", "", "Number of point lights (0 = ambient only). A compile-time loop bound."}, p.lights, 0, 4);
  v.floatParam({"light_power", "Light power", "", "Each light's irradiance at the scene centre; lights sit three scene "
                "radii away and fall off as 1/r^2."}, p.lightPower, 0.0f, 1e5f, true);
  v.floatParam({"light_elevation", "Light elevation", "deg", "Height of the lights above the horizon. Near 0 the "
                "light grazes the floor: N.L -> 0."}, p.lightElevationDeg, -10.0f, 90.0f);
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
  if (mode.perFace) spec.stages.push_back({GL_GEOMETRY_SHADER, "shading/flat.geom"});
  spec.stages.push_back({GL_FRAGMENT_SHADER, "shading/shade.frag"});
  spec.defines.emplace_back(mode.define, "1");
  spec.defines.emplace_back("NUM_LIGHTS", std::to_string(p.lights));
  if (p.specular == SpecularModel::Phong) spec.defines.emplace_back("SPECULAR_PHONG", "1");
  if (p.uvInterpolation == UvInterpolation::Affine) spec.defines.emplace_back("AFFINE_UV", "1");
  if (textured) spec.defines.emplace_back("BASE_COLOR_MAP", "1");
  return spec;
}

std::vector<ProgramSpec> ShadingLab::allPrograms() const {
  std::vector<ProgramSpec> all;
  ShadingParams p;
  for (int mode = 0; mode < int(ShadingMode::Count); ++mode)
    for (int spec = 0; spec < 2; ++spec)
      for (int uv = 0; uv < 2; ++uv)
        for (int textured = 0; textured < 2; ++textured) {
          p.mode = ShadingMode(mode);
          p.specular = SpecularModel(spec);
          p.uvInterpolation = UvInterpolation(uv);
          for (int lights : {0, 4}) {
            p.lights = lights;
            all.push_back(programSpec(p, textured));
          }
        }
  return all;
}

std::string ShadingLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  return {};
}

void ShadingLab::teardown() {
  for (auto& p : programs_) p.reset();
  shaders_ = nullptr;
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

  for (const Instance& inst : frame.scene.instances) {
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
    frame.gpu.draw(inst);
  }
}

std::vector<ProgramRef> ShadingLab::activePrograms() const {
  std::vector<ProgramRef> out;
  for (auto& slot : programs_)
    if (slot.current()) out.push_back(slot.current());
  return out;
}

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
  spec.description = "per-fragment Phong shading on the 256-segment tessellation with perspective-correct UVs, at the "
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
