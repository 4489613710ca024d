// The Lab interface: one family of rendering techniques, its parameters, what it needs from
// the scene, how it draws, what it is judged against and how it is stressed.
//
// Life cycle (driven by app/host/lab_host.cpp):
//   needs() -> host builds exactly that scene -> setup() -> { update(); render(); }* -> teardown()
// render() draws into frame.target, times each pass with frame.pass("name"), and never calls
// ImGui. setup()/teardown() must leave no GL objects behind (tests count them).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/pass_timer.h"
#include "gl/texture.h"
#include "labs/params.h"
#include "measure/image.h"
#include "scene/camera.h"
#include "scene/gpu_scene.h"
#include "scene/scene_catalog.h"
#include "shader/shader_library.h"

namespace shadelab {

using Settings = std::vector<std::pair<std::string, std::string>>;  // "param" -> "value"
using Metrics = std::vector<std::pair<std::string, double>>;

struct LabContext {
  ShaderLibrary& shaders;
};

struct Frame {
  const gl::RenderTarget& target;
  const Scene& scene;
  const GpuScene& gpu;
  const OrbitCamera& camera;
  gl::PassTimer& timer;
  float time = 0.0f;  // seconds; fixed on the command line for repeatable frames

  glm::ivec2 size() const { return target.size(); }
  float aspect() const { return float(target.size().x) / float(std::max(target.size().y, 1)); }
  gl::PassScope pass(std::string name) { return gl::PassScope(timer, std::move(name)); }
};

// The ground truth of a configuration: the same lab with `overrides` applied (e.g. per-fragment
// shading on a finely tessellated mesh), rendered `supersample` times larger and box-filtered.
struct ReferenceSpec {
  Settings overrides;
  int supersample = 1;
  std::string description;
};

// A named extreme configuration. It passes when every pixel is finite and, where given,
// `expectWarning` appears among the lab's warnings (the lab noticed and told the student).
struct StressCase {
  std::string name;
  Settings settings;
  std::string scene;          // "" = the lab's default
  std::string camera;         // "" = framed; else OrbitCamera::parse text
  std::string expectWarning;  // substring of a warning the lab must raise, or ""
};

struct SweepAxis {
  std::string key;  // param key within the lab
  std::vector<std::string> values;
};

class Lab {
 public:
  virtual ~Lab() = default;
  virtual std::string_view id() const = 0;
  virtual std::string_view title() const = 0;
  virtual std::string_view summary() const = 0;
  virtual std::string_view defaultScene() const = 0;
  // Scenes this lab brings (listed first while it is the current lab).
  virtual std::vector<SceneRecipe> scenes() const { return {}; }

  virtual void visitParams(ParamVisitor& v) = 0;
  virtual void resetParams() = 0;
  virtual SceneNeeds needs() const = 0;
  // Every program the lab can use, each variant once: `check-shaders` compiles them all.
  virtual std::vector<ProgramSpec> allPrograms() const = 0;

  virtual std::string setup(LabContext& ctx) = 0;  // "" or a one-line error
  virtual void teardown() = 0;
  virtual void update(float dt) {}
  virtual void render(Frame& frame) = 0;
  // Programs used by the current configuration (for the Shaders panel and error display).
  virtual std::vector<ProgramRef> activePrograms() const = 0;
  // What the current configuration clamped, fell back on or cannot do well; shown in the UI.
  virtual std::vector<std::string> warnings() const { return {}; }

  // The ground truth. By default the host renders reference() (overrides + supersampling).
  // A lab whose truth is not a rasterised image (ray-traced visibility) returns it here instead,
  // for the current settings, at frame.size(); std::nullopt means "use reference()".
  virtual ReferenceSpec reference() const { return {}; }
  virtual std::optional<ImageF> computeReference(Frame& frame) { return std::nullopt; }
  // Settings applied for the image that is compared with the reference (the shadows lab outputs
  // its visibility term); the cost is always timed on the normal view.
  virtual Settings measuredView() const { return {}; }
  // Error numbers of `image` against `reference`; errorKeys() are the ones plotted against cost.
  virtual Metrics metrics(const ImageF& image, const ImageF& reference) const;
  virtual std::vector<std::string> errorKeys() const { return {"rmse", "surface_rmse"}; }
  virtual std::vector<StressCase> stressCases() const { return {}; }
  virtual std::vector<SweepAxis> standardSweep() const { return {}; }
};

// Holds the Params struct, so resetting is `params = Params{}` and nothing else.
template <typename P>
class LabWithParams : public Lab {
 public:
  void resetParams() override { params = P{}; }
  P params;
};

// labs/registry.cpp: the explicit list of labs (no static self-registration).
std::vector<std::string> labIds();
std::unique_ptr<Lab> makeLab(std::string_view id);  // null if unknown

}  // namespace shadelab
