// Shading lab: how often lighting is evaluated (per face, per vertex, per fragment), Phong vs
// Blinn-Phong highlights, inverse-square point lights, and perspective-correct vs affine
// texture interpolation on a checker floor. GAMES101 lectures 7-9.
// Reference: per-fragment Phong shading on the finest tessellation (true geometry up to
// 256 segments), with perspective-correct UVs. Read next: shaders/shading/shade.frag.
#pragma once
#include <vector>

#include "app/lab/lab.h"
#include "app/scene/gpu_mesh.h"

namespace shadelab {

enum class ShadingMode { Flat, Gouraud, Phong, Count };  // a table in shading_lab.cpp
enum class SpecularModel { BlinnPhong, Phong, Count };
enum class UvInterpolation { Perspective, Affine, ByHand, Count };
// How flat mode gives each triangle one normal and one colour.
enum class FlatFaces { GeometryShader, Unwelded, Count };

struct ShadingParams {
  ShadingMode mode = ShadingMode::Phong;
  SpecularModel specular = SpecularModel::BlinnPhong;
  UvInterpolation uvInterpolation = UvInterpolation::Perspective;
  int tessellation = 16;                            // segments around spheres and tori
  float ka = 0.15f;                                 // ambient reflectance
  float kd = 0.8f;                                  // diffuse reflectance
  float ks = 0.5f;                                  // specular reflectance
  float shininess = 64.0f;                          // specular exponent p
  int lights = 2;                                   // point lights in use, 0..4
  float lightPower = 0.8f;                          // irradiance at the scene centre (so any scene size looks alike)
  float lightElevationDeg = 45;                     // height of the lights above the horizon; near 0 = grazing
  bool textures = true;                             // base-colour textures (the checker floor, OBJ/glTF maps)
  FlatFaces flatFaces = FlatFaces::GeometryShader;  // WebGL2 has no geometry shaders: always unwelded there
};

class ShadingLab final : public LabWithParams<ShadingParams>, public Judge {
 public:
  static constexpr int kReferenceTessellation = 256;

  std::string_view id() const override { return "shading"; }
  std::string_view title() const override { return "Shading: flat, Gouraud, Phong"; }
  std::string_view summary() const override;
  std::string_view defaultScene() const override { return "shading"; }

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override;
  std::vector<ProgramSpec> allPrograms() const override;
  InspectedPass inspectedPass() const override { return {"shading/shade.frag", "main"}; }

  std::string setup(LabContext& ctx) override;
  void render(Frame& frame) override;
  std::vector<ProgramRef> activePrograms() const override;
  std::vector<std::string> warnings() const override;

  // Judge: the lab is its own.
  Judge* judge() override { return this; }
  ReferenceSpec reference() const override;
  std::vector<StressCase> stressCases() const override;
  std::vector<SweepAxis> standardSweep() const override;

 private:
  ProgramSpec programSpec(const ShadingParams& p, bool textured) const;

  // Flat mode without a geometry shader: each of the scene's meshes with three vertices of its own
  // per triangle, carrying the face's normal and centroid; rebuilt with the scene.
  std::vector<GpuMesh> unwelded_;
  int unweldedRevision_ = -1;

  ShaderLibrary* shaders_ = nullptr;
  // Built on demand, per variant actually drawn; a param change that alters the defines fetches
  // (or compiles) the right one.
  ProgramSlot programs_[2];  // [untextured, textured]
};

}  // namespace shadelab
