// Minimal lab: the skeleton every lab grows from. One light, one program, two parameters: a
// float the shader reads as a uniform and a choice compiled in as a #define. No truth, so no Judge.
// Copy this folder to start a lab (labs/README.md); labs/shading is the full example with a truth.
// Read next: shaders/minimal/minimal.frag.
#pragma once
#include "app/lab/lab.h"

namespace shadelab {

enum class MinimalView { Lit, Normals, Count };

struct MinimalParams {
  MinimalView view = MinimalView::Lit;
  float lightElevationDeg = 40.0f;  // the light's height above the horizon
};

class MinimalLab final : public LabWithParams<MinimalParams> {
 public:
  std::string_view id() const override { return "minimal"; }
  std::string_view title() const override { return "Minimal: the skeleton of a lab"; }
  std::string_view summary() const override {
    return "One directional light, Lambert's cosine law, and a view of the normals. The smallest lab: the "
           "one to copy when you write your own (labs/minimal).";
  }
  std::string_view defaultScene() const override { return "shading"; }

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override { return {}; }  // positions and normals: no textures, no tangents
  std::vector<ProgramSpec> allPrograms() const override;

  std::string setup(LabContext& ctx) override;
  void render(Frame& frame) override;
  std::vector<ProgramRef> activePrograms() const override { return heldPrograms({&program_, 1}); }

 private:
  ProgramSpec programSpec(MinimalView view) const;

  ShaderLibrary* shaders_ = nullptr;
  ProgramSlot program_;  // re-fetched only when the view (its #define) changes
};

}  // namespace shadelab
