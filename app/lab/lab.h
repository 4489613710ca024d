// The lab contract: one family of rendering techniques, its parameters, what it needs from the
// scene and how it draws (Lab), and, where it has a truth, how it is judged and stressed (Judge).
//
// Life cycle (driven by app/host/lab_host.cpp):
//   needs() -> host builds exactly that scene -> setup() -> { update(); render(); }* -> destroyed
// render() draws into frame.target, times each pass with frame.pass("name"), and never calls
// ImGui. A lab holds its GL objects in RAII members (app/gl/handle.h), so destroying it, which
// the host does with the context current, leaves none behind (tests count them). Long CPU work
// (smoothing a mesh, a bake) goes to ctx.jobs from update(); render() draws the last result.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/gl/pass_timer.h"
#include "app/gl/texture.h"
#include "app/lab/lab_panel.h"
#include "app/lab/params.h"
#include "app/measure/accumulator.h"
#include "app/measure/image.h"
#include "app/measure/report.h"
#include "app/scene/camera.h"
#include "app/scene/gpu_scene.h"
#include "app/scene/scene_catalog.h"
#include "app/shader/shader_library.h"
#include "app/util/job_runner.h"

namespace shadelab {

using Settings = std::vector<std::pair<std::string, std::string>>;  // "param" -> "value"
using Metrics = std::vector<std::pair<std::string, double>>;

struct LabContext {
  ShaderLibrary& shaders;
  JobRunner& jobs;
};

struct Frame {
  const gl::RenderTarget& target;
  const Scene& scene;
  const GpuScene& gpu;
  const OrbitCamera& camera;
  gl::PassTimer& timer;
  float time = 0.0f;       // seconds; fixed on the command line for repeatable frames
  glm::vec2 jitter{0.0f};  // sub-pixel shift of the image, in pixels (accumulated references)
  // A heavy truth frame is drawn in `slices` calls, so the window draws its own frames between
  // them (ReferenceSpec::slices): call `slice` clears only if it is the first and draws its share
  // of the triangles, which the depth test composes into the one frame a single call would draw.
  int slice = 0, slices = 1;

  glm::ivec2 size() const { return target.size(); }
  float aspect() const { return float(target.size().x) / float(std::max(target.size().y, 1)); }
  gl::PassScope pass(std::string name) { return gl::PassScope(timer, std::move(name)); }
  // The camera's projection, shifted by `jitter`: labs use these, never the camera's own.
  glm::mat4 projection() const {
    const glm::vec2 shift = -2.0f * jitter / glm::vec2(size());  // sample centre + jitter: the image moves by -jitter
    return glm::translate(glm::mat4(1.0f), glm::vec3(shift.x, -shift.y, 0.0f)) * camera.projection(aspect());
  }
  glm::mat4 viewProj() const { return projection() * camera.view(); }
};

enum class TruthKind {
  None,   // nothing to judge this configuration against
  Image,  // an image of the same pixels: the lab under `overrides`, or traced by the lab itself
  Mesh,   // the clean mesh: the lab compares its own geometry and reports meshMetrics()
};

// The ground truth of a configuration.
struct ReferenceSpec {
  TruthKind kind = TruthKind::None;
  std::string truth = "reference";  // which truth: a sweep draws one Pareto front per truth
  std::string description;          // one sentence for reports
  // Image truths: the same lab with `overrides` applied, accumulated over jitterGrid x jitterGrid
  // frames shifted by sub-pixel offsets (measure/accumulator.h) at the frame's own size ...
  Settings overrides;
  int jitterGrid = 1;
  PixelFilter pixelFilter = PixelFilter::Box;
  bool displayEncoded = true;  // the frames are sRGB colour (averaged in linear light), not data
  // ... or traced by the lab (traceReference) when that is what the truth is; on the GPU in GL
  // steps (traceReferenceOnGl) rather than in a CPU job when `tracedOnGl`.
  bool traced = false;
  bool tracedOnGl = false;
  bool cheap = false;  // quick enough to measure after every change: the app offers auto-measure
  // An image truth's frames are drawn in this many parts (Frame::slice), each a GL step of its own
  // in the window: a lab whose truth draws millions of triangles keeps the window's frame time.
  int slices = 1;
};

// The CPU part of a traced truth: runs in a job, reports progress, stops when cancelled.
using TraceWork = std::function<ImageF(JobContext&)>;
// A truth traced on the GPU a pass at a time: each call (on the GL thread, between the window's
// frames) adds a pass, reports progress, and returns the image once it is complete.
using GlTraceStep = std::function<std::optional<ImageF>(JobContext&)>;

// One view a lab's metrics compare: the lab under `settings`, against the truth drawn in it.
struct MeasuredView {
  Settings settings;
  bool displayEncoded = true;  // sRGB colour (averaged in linear light), or data (normals) as stored
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

class Judge;

// Drawing: what every lab implements.
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

  virtual std::string setup(LabContext& ctx) = 0;  // "" or a one-line error; the lab is destroyed either way
  // Once per frame before render(), with the scene built for needs(): where a lab submits jobs
  // for derived results whose inputs changed, and uploads results that arrived.
  virtual void update(const Scene& scene, float dt) {}
  // Whether the frame changes with time alone (an animated camera): the window keeps drawing while
  // it does, and otherwise stops drawing when nothing moves.
  virtual bool animating() const { return false; }
  virtual void render(Frame& frame) = 0;
  // Programs used by the current configuration (for the Shaders panel and error display).
  virtual std::vector<ProgramRef> activePrograms() const = 0;
  // What the current configuration clamped, fell back on or cannot do well; shown in the UI.
  virtual std::vector<std::string> warnings() const { return {}; }
  // Views of the lab's own beside the parameters (app/lab/lab_panel.h): tables, plots, images.
  virtual std::vector<LabPanel> panels() const { return {}; }

  // The camera pass the inspector traces at a pixel when no exercise is open (grade/pixel_trace.h):
  // the fragment shader's file and the function whose values make the frame; empty: none.
  struct InspectedPass {
    std::string file, function;
  };
  virtual InspectedPass inspectedPass() const { return {}; }

  // How the lab is judged, or null: a lab without a truth, metrics or stress cases has no Judge
  // and implements nothing below. A lab that judges usually is its own Judge (returns this).
  virtual Judge* judge() { return nullptr; }
  const Judge* judge() const { return const_cast<Lab*>(this)->judge(); }
};

// Judging: the truth a lab's configurations are measured against, the error numbers, what a
// sweep varies and plots, and the extreme configurations the stress runner tries.
class Judge {
 public:
  virtual ~Judge() = default;
  // The ground truth of the current configuration (app/host/measurer.h measures against it).
  virtual ReferenceSpec reference() const = 0;
  // Traced truths: called with the truth's settings applied; does the GL part now (a g-buffer of
  // frame's pixels) and returns the CPU part, which must own everything it reads.
  virtual TraceWork traceReference(Frame& frame) { return {}; }
  // The same for a truth traced on the GPU: the g-buffer now, then one GL step per pass.
  virtual GlTraceStep traceReferenceOnGl(Frame& frame) { return {}; }
  // Settings applied for the image that is compared with an image truth (the shadows lab outputs
  // its visibility term); the cost is always timed on the normal view.
  virtual Settings measuredView() const { return {}; }
  // Several views, each compared with the truth drawn in the same view (a shaded image and its
  // normals, say). One by default: measuredView(), encoded as the reference says.
  virtual std::vector<MeasuredView> measuredViews() const { return {{measuredView(), reference().displayEncoded}}; }
  // Error numbers of `image` against an image truth.
  virtual Metrics metrics(const ImageF& image, const ImageF& reference) const;
  // Error numbers over every measured view: images[i] against references[i]. By default the first.
  virtual Metrics viewMetrics(const std::vector<ImageF>& images, const std::vector<ImageF>& references) const {
    return metrics(images.at(0), references.at(0));
  }
  // Mesh truths: the current result against the clean mesh, with the lab's own costs (solve_ms).
  // Asked only when no job of the lab is running, so the numbers belong to the current settings.
  virtual Metrics meshMetrics() const { return {}; }
  // What a sweep and the app's Measure panel plot.
  virtual std::vector<PlotSpec> plots() const { return {{"rmse"}, {"surface_rmse"}}; }
  // What a metric measures and what it is divided by, where its name does not say: metric ->
  // one sentence. A sweep's CSV opens with them as "# key: note" lines.
  virtual Settings metricNotes() const { return {}; }
  virtual std::vector<StressCase> stressCases() const { return {}; }
  virtual std::vector<SweepAxis> standardSweep() const { return {}; }
};

// The truth of the lab's current configuration: none for a lab without a Judge.
ReferenceSpec referenceOf(const Lab& lab);
// The extreme configurations the stress runner tries: none for a lab without a Judge.
std::vector<StressCase> stressCasesOf(const Lab& lab);

// Holds the Params struct, so resetting is `params = Params{}` and nothing else.
template <typename P>
class LabWithParams : public Lab {
 public:
  void resetParams() override { params = P{}; }
  P params;

 protected:
  // What `edit` changes in `base`, as the settings text --set, presets and the host take: truths'
  // overrides, measured views and stress cases written as edits of the Params struct, which the
  // compiler checks, rather than key/value strings checked only when they run. `LabType` is the
  // lab's own class (a probe of it lists the parameters); its visitParams must list the same keys
  // whatever their values.
  //   spec.overrides = edits<ShadowsLab>(params, [](ShadowsParams& p) { p.filter = ShadowFilter::Hard; });
  template <typename LabType, typename Edit>
  static Settings edits(const P& base, Edit&& edit) {
    LabType probe;
    probe.params = base;
    CollectAsText before;
    probe.visitParams(before);
    edit(probe.params);
    CollectAsText after;
    probe.visitParams(after);
    Settings changed;
    for (size_t i = 0; i < after.values.size(); ++i)
      if (i >= before.values.size() || after.values[i] != before.values[i]) changed.push_back(after.values[i]);
    return changed;
  }
  // The same, from the defaults: stress cases and other configurations applied to a fresh lab.
  template <typename LabType, typename Edit>
  static Settings fromDefaults(Edit&& edit) {
    return edits<LabType>(P{}, std::forward<Edit>(edit));
  }
};

// The labs, in the order the app lists them: one table in labs/registry.cpp (no static
// self-registration, which linkers drop when a lab's object file is otherwise unreferenced).
struct LabEntry {
  std::string_view id;
  std::unique_ptr<Lab> (*make)();
  bool inMenu = true;  // offered in the window's and the page's lab menu; the skeleton lab is not
};
std::span<const LabEntry> labRegistry();
std::vector<std::string> labIds();                  // every lab: the CLI, the soak and the tests
std::vector<std::string> menuLabIds();              // the labs a student picks from
std::unique_ptr<Lab> makeLab(std::string_view id);  // null if unknown

}  // namespace shadelab
