// The lab host: one current lab, one scene built for exactly what that lab needs, a camera, an
// offscreen target, the shader library and the job runner. Every front end (window, render,
// sweep, stress, tests) drives labs through this class, so they all render the same frames.
// Measuring against ground truth lives beside it (host/measurer.h, host/truth.h).
//
// Errors never lose state: a failed lab switch, scene load or setting leaves the last good one
// in place and returns a one-line message.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/gl/stand_ins.h"
#include "app/host/preset.h"
#include "app/lab/lab.h"
#include "app/measure/image.h"
#include "app/util/job_runner.h"

namespace shadelab {

class LabHost {
 public:
  // Needs a current GL context. `shaderPath`: the student's folders first, then shaders/.
  // `firstLab`, `firstScene`: what is set up first (the first of labIds() when empty or unknown,
  // the lab's default scene when empty or when it does not build), so that a caller who wants one
  // lab and scene does not build another on the way; sceneId() says which scene was built.
  explicit LabHost(ShaderSearchPath shaderPath, std::string_view firstLab = {}, const std::string& firstScene = {});
  ~LabHost();

  std::string selectLab(std::string_view id) { return enterLab(id, {}); }
  std::string selectScene(const std::string& idOrPath);
  // An image (PNG, JPEG, ...) as the height map of every material of the current scene, white =
  // high (a lab may read it as depth): a user's own relief for a mesh whose file has none. Kept
  // until another scene or lab is picked; "" drops it. Returns "" or a one-line error naming the file.
  std::string setHeightMap(const std::string& imageFile);
  const std::string& heightMap() const { return heightMap_; }
  // Rebuilds the scene now if the lab's needs changed since it was built (else at the next frame).
  std::string refreshScene() { return ensureScene(); }
  // "lab.key=value" or "key=value" (the current lab); errors name the valid keys.
  std::string set(const std::string& assignment);
  // "lab.key" or "key": runs one of the lab's actions; errors name the valid ones.
  std::string runAction(const std::string& key);
  std::string applySettings(const Settings& settings);
  Settings currentSettings();  // every param of the current lab as text
  // The current lab's defaults on the current scene: its own, with the scene's suggested settings
  // for it (Scene::suggestedSettings) over them. resetParams() returns to them.
  Settings defaultSettings();
  void resetParams();
  void resetCamera();

  // Delivers finished jobs, makes the scene match the lab's needs, reloads changed shaders,
  // lets the lab update and renders one frame into the view's target.
  // Between frames of a window that has stopped drawing: rebuilds programs whose files were saved
  // and takes finished jobs' results; true when either happened, so that the frame is drawn.
  bool pollChanges();
  const std::vector<gl::PassTiming>& renderFrame(glm::ivec2 size, float time = 0.0f, float dt = 0.0f);
  ImageF readImage() const { return {target_->size(), target_->readRgba()}; }
  // One frame of the current settings into `target` as `camera` sees it, shifted by `jitter`
  // pixels: no reload, no job delivery. For references; the view's target is left alone. With
  // `slices` > 1, part `slice` of the frame (Frame::slice): all of them in order make the frame.
  std::vector<gl::PassTiming> drawInto(const gl::RenderTarget& target, const OrbitCamera& camera, float time,
                                       glm::vec2 jitter = glm::vec2(0.0f), int slice = 0, int slices = 1);
  // Traced truths: the lab's GL part (a g-buffer of `target`'s pixels as `camera` sees them);
  // returns the CPU part for a job. Settings as they are now: apply the truth's first.
  TraceWork trace(const gl::RenderTarget& target, const OrbitCamera& camera, float time);
  GlTraceStep traceOnGl(const gl::RenderTarget& target, const OrbitCamera& camera, float time);
  // Headless runs and tests: lets the lab submit what the current settings need, then waits for
  // every job and delivers it, until none is left. onProgress sees the running jobs.
  void settle(const std::function<void(const std::vector<JobStatus>&)>& onProgress = {});
  // The lab's ground truth for the current settings, blocking (host/truth.h); restores settings.
  ImageF renderReference(glm::ivec2 size, float time = 0.0f);
  // The frame the metrics compare: rendered with the lab's measuredView() settings, or `view`.
  ImageF renderMeasured(glm::ivec2 size, float time = 0.0f);
  ImageF renderView(glm::ivec2 size, float time, const Settings& view);

  // Lab, params, scene, camera: everything a headless run needs to reproduce a frame.
  nlohmann::json stateJson();
  std::string applyStateJson(const nlohmann::json& state);
  std::string applyPreset(const Preset& preset);  // lab, scene, params (all or none), camera

  Lab& lab() { return *lab_; }
  const std::string& sceneId() const { return sceneId_; }
  // Counts scene loads (a new id or file), not rebuilds for new needs: truth caches key on it.
  int sceneLoads() const { return sceneLoads_; }
  // Counts lab entries (a lab left and entered again counts twice): what belongs to one stay in a
  // lab (a measurer's truths) is let go when it changes.
  int labEntries() const { return labEntries_; }
  const Scene& scene() const { return built_.scene; }
  const GpuScene& gpuScene() const { return built_.gpu; }
  OrbitCamera& camera() { return camera_; }
  ShaderLibrary& shaders() { return *shaders_; }
  JobRunner& jobs() { return jobs_; }
  const gl::RenderTarget* target() const { return target_ ? &*target_ : nullptr; }
  const std::vector<gl::PassTiming>& lastPasses() const { return timer_.lastFrame(); }
  // Scene warnings (loader, degenerate UVs, missing textures), the lab's own, and failed jobs'.
  std::vector<std::string> warnings() const;
  int sceneBuilds() const { return sceneBuilds_; }
  const char* timerClock() const { return timer_.clockName(); }

 private:
  std::string enterLab(std::string_view id, const std::string& scene);  // "" = the lab's default scene
  // A scene built for one set of needs, uploaded.
  struct Built {
    Scene scene;
    GpuScene gpu;
    SceneNeeds needs;
    std::vector<std::string> warnings;
  };
  std::string ownKey(const std::string& key) const;
  // After a scene is picked: the settings the scene left (`leaving`, its suggestions) back to the
  // lab's defaults, then the new scene's suggestions applied.
  void applySceneSettings(const std::vector<std::string>& leaving);
  std::string ensureScene();
  std::vector<gl::PassTiming> draw(gl::PassTimer& timer, const gl::RenderTarget& target, const OrbitCamera& camera,
                                   float time, glm::vec2 jitter, int slice = 0, int slices = 1);
  std::string rebuildScene(const std::string& id, const SceneNeeds& needs, bool reframe);
  // The GL part of a traced truth: `begin` gets the lab's judge and a frame on the truth's timer.
  void traceFrame(const gl::RenderTarget& target, const OrbitCamera& camera, float time,
                  const std::function<void(Judge&, Frame&)>& begin);
  std::string heightMap_;  // setHeightMap's image, applied to every build of the current scene

  std::unique_ptr<ShaderLibrary> shaders_;
  // What llvmpipe holds in place of a left lab's textures (gl/driver_caveats.h, HeldTextures):
  // made with the host where that driver runs, absent on any other.
  std::unique_ptr<gl::DriverStandIns> standIns_;
  JobRunner jobs_;  // before lab_: jobs are cancelled before a lab goes
  std::unique_ptr<Lab> lab_;
  std::string sceneId_;
  int sceneLoads_ = 0;
  int labEntries_ = 0;
  // The scene for the current needs and the one built before it: flipping between two sets of
  // needs (a reference's tessellation and the view's) swaps them instead of rebuilding.
  Built built_;
  std::optional<Built> previous_;
  OrbitCamera camera_;
  std::optional<gl::RenderTarget> target_;      // the view's frames
  std::optional<gl::RenderTarget> sideTarget_;  // measured views, off screen
  gl::PassTimer timer_;                         // the view's frames: what the Cost panel shows
  gl::PassTimer truthTimer_;                    // reference frames, kept out of the view's numbers
  std::vector<std::string> jobErrors_;
  int sceneBuilds_ = 0;
};

}  // namespace shadelab
