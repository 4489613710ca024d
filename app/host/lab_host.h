// The lab host: one current lab, one scene built for exactly what that lab needs, a camera, an
// offscreen target and the shader library. Every front end (window, render, sweep, stress,
// tests) drives labs through this class, so they all render the same frames.
//
// Errors never lose state: a failed lab switch, scene load or setting leaves the last good one
// in place and returns a one-line message.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "labs/lab.h"
#include "measure/image.h"

namespace shadelab {

class LabHost {
 public:
  // Needs a current GL context. `shaderPath`: the student's folders first, then shaders/.
  explicit LabHost(ShaderSearchPath shaderPath);
  ~LabHost();

  std::string selectLab(std::string_view id);
  std::string selectScene(const std::string& idOrPath);
  // Rebuilds the scene now if the lab's needs changed since it was built (else at the next frame).
  std::string refreshScene() { return ensureScene(); }
  // "lab.key=value" or "key=value" (the current lab); errors name the valid keys.
  std::string set(const std::string& assignment);
  // "lab.key" or "key": runs one of the lab's actions; errors name the valid ones.
  std::string runAction(const std::string& key);
  std::string applySettings(const Settings& settings);
  Settings currentSettings();  // every param of the current lab as text
  void resetParams();
  void resetCamera();

  // Makes the scene match the lab's needs, reloads changed shaders, renders one frame.
  const std::vector<gl::PassTiming>& renderFrame(glm::ivec2 size, float time = 0.0f, float dt = 0.0f);
  ImageF readImage() const { return {target_->size(), target_->readRgba()}; }
  // The lab's ground truth for the current settings (computeReference, else ReferenceSpec);
  // restores the settings.
  ImageF renderReference(glm::ivec2 size, float time = 0.0f);
  // The frame the metrics compare: rendered with the lab's measuredView() settings.
  ImageF renderMeasured(glm::ivec2 size, float time = 0.0f);

  // Lab, params, scene, camera: everything a headless run needs to reproduce a frame.
  nlohmann::json stateJson();
  std::string applyStateJson(const nlohmann::json& state);

  Lab& lab() { return *lab_; }
  const std::string& sceneId() const { return sceneId_; }
  const Scene& scene() const { return scene_; }
  const GpuScene& gpuScene() const { return gpu_; }
  OrbitCamera& camera() { return camera_; }
  ShaderLibrary& shaders() { return *shaders_; }
  const gl::RenderTarget* target() const { return target_ ? &*target_ : nullptr; }
  const std::vector<gl::PassTiming>& lastPasses() const { return timer_.lastFrame(); }
  // Scene warnings (loader, degenerate UVs, missing textures) and the lab's own.
  std::vector<std::string> warnings() const;
  int sceneBuilds() const { return sceneBuilds_; }
  const char* timerClock() const { return timer_.clockName(); }

 private:
  std::string ownKey(const std::string& key) const;
  std::string ensureScene();
  std::string rebuildScene(const std::string& id, const SceneNeeds& needs, bool reframe);

  std::unique_ptr<ShaderLibrary> shaders_;
  std::unique_ptr<Lab> lab_;
  bool labReady_ = false;
  std::string sceneId_;
  SceneNeeds builtNeeds_;
  Scene scene_;
  GpuScene gpu_;
  std::vector<std::string> sceneWarnings_;
  OrbitCamera camera_;
  std::optional<gl::RenderTarget> target_;
  gl::PassTimer timer_;
  int sceneBuilds_ = 0;
};

}  // namespace shadelab
