#include "labs/minimal/minimal_lab.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "app/lab/technique.h"

namespace shadelab {
namespace {
constexpr Named<MinimalView> kViewNames[] = {{MinimalView::Lit, "lit"}, {MinimalView::Normals, "normals"}};
static_assert(coversEnum<MinimalView>(kViewNames));
}  // namespace

void MinimalLab::visitParams(ParamVisitor& v) {
  v.section("Minimal");
  v.enumParam({"view", "View", "",
               "lit: Lambert's max(N.L, 0) under one white light; normals: the world normal "
               "as colour (0.5 n + 0.5). A compile-time choice: each view is its own program."},
              params.view, namesOf<kViewNames>());
  v.floatParam({"light_elevation", "Light elevation", "deg",
                "Height of the light above the horizon: at 90 it shines "
                "straight down, near 0 it grazes the floor. A uniform: no recompile."},
               params.lightElevationDeg, 0.0f, 90.0f);
}

ProgramSpec MinimalLab::programSpec(MinimalView view) const {
  ProgramSpec spec;
  spec.name = "minimal/" + std::string(rowOf(kViewNames, view).name);
  spec.stages = {{GL_VERTEX_SHADER, "minimal/minimal.vert"}, {GL_FRAGMENT_SHADER, "minimal/minimal.frag"}};
  if (view == MinimalView::Normals) spec.defines.emplace_back("VIEW_NORMALS", "1");
  return spec;
}

std::vector<ProgramSpec> MinimalLab::allPrograms() const {
  return {programSpec(MinimalView::Lit), programSpec(MinimalView::Normals)};
}

std::string MinimalLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  return {};
}

void MinimalLab::render(Frame& frame) {
  auto pass = frame.pass("shade");
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);  // alpha 0 marks the background
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  const float elevation = glm::radians(params.lightElevationDeg);
  const glm::vec3 toLight(0.6f * std::cos(elevation), std::sin(elevation), 0.8f * std::cos(elevation));  // unit length
  Program& prog = program_.get(*shaders_, programSpec(params.view));
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  if (params.view == MinimalView::Lit) prog.set("u_toLight", toLight);  // the normals view has no light
  for (const Instance& inst : frame.scene.instances) {
    prog.set("u_model", inst.model);
    prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(inst.model)));
    if (params.view == MinimalView::Lit)
      prog.set("u_albedo",
               glm::vec3(frame.scene.materials[size_t(frame.scene.meshes[size_t(inst.mesh)].material)].baseColor));
    frame.gpu.draw(inst);
  }
}

}  // namespace shadelab
