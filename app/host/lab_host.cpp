#include "app/host/lab_host.h"

#include <algorithm>

#include "app/gl/driver_caveats.h"
#include "app/host/truth.h"
#include "app/scene/scene_catalog.h"

namespace shadelab {

LabHost::LabHost(ShaderSearchPath shaderPath, std::string_view firstLab, const std::string& firstScene)
    : shaders_(std::make_unique<ShaderLibrary>(std::move(shaderPath))) {
  if (gl::applies(gl::Caveat::HeldTextures)) standIns_ = std::make_unique<gl::DriverStandIns>();
  const std::vector<std::string> ids = labIds();
  const bool known = std::find(ids.begin(), ids.end(), firstLab) != ids.end();
  if (!known || !enterLab(firstLab, firstScene).empty()) selectLab(known ? firstLab : std::string_view(ids.front()));
}

LabHost::~LabHost() {
  jobs_.cancelAll();
  lab_.reset();  // its GL objects go while the context is current, before the shader library it holds programs of
}

std::string LabHost::enterLab(std::string_view id, const std::string& firstScene) {
  auto next = makeLab(id);
  if (!next) {
    std::string valid;
    for (auto& l : labIds()) valid += (valid.empty() ? "" : ", ") + l;
    return "unknown lab '" + std::string(id) + "' (valid: " + valid + ")";
  }
  LabContext ctx{*shaders_, jobs_};
  if (auto err = next->setup(ctx); !err.empty()) return std::string(id) + ": setup failed: " + err;
  jobs_.cancelAll();   // nothing of the old lab may be delivered to the new one
  jobErrors_.clear();  // nor shown in it: its failed jobs were about its own settings
  if (lab_) {
    lab_.reset();                                      // the old lab's GL objects go with it
    if (standIns_) standIns_->takeDriverReferences();  // else llvmpipe keeps the old lab's biggest maps
  }
  sideTarget_.reset();       // the old lab's measured views: a lab starts with the objects it makes itself
  shaders_->forgetRecent();  // the old lab's variants
  lab_ = std::move(next);
  ++labEntries_;
  const std::string scene = firstScene.empty() ? std::string(lab_->defaultScene()) : firstScene;
  heightMap_.clear();
  const std::string err = rebuildScene(scene, lab_->needs(), true);
  previous_.reset();                        // the old lab's scene, which rebuildScene kept: of no use to this lab
  if (err.empty()) applySceneSettings({});  // a new lab starts at its defaults: nothing to restore
  return err;
}

std::string LabHost::selectScene(const std::string& idOrPath) {
  std::string kept;
  std::swap(kept, heightMap_);  // a height map belongs to the scene it was given for
  const std::vector<std::string> leaving = built_.scene.suggestedSettings;
  const std::string err = rebuildScene(idOrPath, lab_->needs(), true);
  if (err.empty()) {
    previous_.reset();  // another scene: the old builds are of no further use
    applySceneSettings(leaving);
  } else {
    heightMap_ = kept;
  }
  return err;
}

std::string LabHost::setHeightMap(const std::string& imageFile) {
  if (!imageFile.empty()) {
    ImageSource probe;
    probe.name = imageFile;
    probe.file = imageFile;
    std::vector<unsigned char> rgba;
    glm::ivec2 size;
    if (std::error_code ec; !std::filesystem::is_regular_file(probe.file, ec)) return imageFile + ": no such file";
    if (auto err = decodeImage(probe, rgba, size); !err.empty()) return err;
  }
  const std::string before = heightMap_;
  heightMap_ = imageFile;
  const std::string err = rebuildScene(sceneId_, lab_->needs(), false);
  if (!err.empty()) heightMap_ = before;
  previous_.reset();  // built with the other height map
  return err;
}

std::string LabHost::rebuildScene(const std::string& id, const SceneNeeds& needs, bool reframe) {
  Built next;
  if (auto err = buildScene(id, needs, next.scene, lab_->scenes()); !err.empty()) return err;
  if (!heightMap_.empty()) {
    ImageSource image;
    image.name = std::filesystem::path(heightMap_).filename().string();
    image.file = heightMap_;
    next.scene.images.push_back(std::move(image));
    for (Material& m : next.scene.materials) {
      m.heightImage = int(next.scene.images.size()) - 1;
      m.heightIsDepth = false;
    }
  }
  next.warnings = next.scene.warnings;
  next.gpu.upload(next.scene, needs, next.warnings);
  next.scene.revision = ++sceneBuilds_;
  next.needs = needs;
  if (id != sceneId_) ++sceneLoads_;
  previous_ = std::move(built_);
  built_ = std::move(next);
  sceneId_ = id;
  if (reframe) resetCamera();
  return {};
}

std::string LabHost::ensureScene() {
  const SceneNeeds needs = lab_->needs();
  if (needs == built_.needs && !sceneId_.empty()) return {};
  if (needs.sameButSampling(built_.needs) && !sceneId_.empty()) {  // filters, wrap, anisotropy: re-sample
    built_.gpu.applySampling(built_.scene, needs);
    built_.needs.sampling = needs.sampling;
    return {};
  }
  if (previous_ && previous_->needs == needs) {
    std::swap(built_, *previous_);
    return {};
  }
  // A new scale moves everything: frame it again. Other needs (tessellation, UVs) keep the view.
  return rebuildScene(sceneId_, needs, needs.scale != built_.needs.scale);
}

void LabHost::resetCamera() {
  const Bounds b = built_.scene.bounds;
  camera_ = OrbitCamera{};
  camera_.frame(b.center(), b.radius());
  if (!built_.scene.suggestedCamera.empty() && camera_.parse(built_.scene.suggestedCamera).empty())
    camera_.fitDepthRange(b.center(), b.radius());
}

// "lab.key" -> "key" for the current lab; "" when it names another lab.
std::string LabHost::ownKey(const std::string& key) const {
  const std::string prefix = std::string(lab_->id()) + ".";
  if (key.rfind(prefix, 0) == 0) return key.substr(prefix.size());
  return key.find('.') == std::string::npos ? key : std::string();
}

std::string LabHost::set(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos)
    return "'" + assignment + "': expected key=value, e.g. " + std::string(lab_->id()) + ".mode=phong";
  const std::string key = ownKey(assignment.substr(0, eq));
  if (key.empty())
    return "'" + assignment.substr(0, eq) + "' belongs to another lab (the current lab is " + std::string(lab_->id()) +
           ")";
  SetFromString setter(lab_->id(), key, assignment.substr(eq + 1));
  lab_->visitParams(setter);
  return setter.result();
}

std::string LabHost::runAction(const std::string& name) {
  const std::string key = ownKey(name);
  if (key.empty()) return "'" + name + "' belongs to another lab (the current lab is " + std::string(lab_->id()) + ")";
  RunAction run(lab_->id(), key);
  lab_->visitParams(run);
  return run.result();
}

std::string LabHost::applySettings(const Settings& settings) {
  for (auto& [k, v] : settings)
    if (auto err = set(k + "=" + v); !err.empty()) return err;
  return {};
}

Settings LabHost::currentSettings() {
  CollectAsText c;
  lab_->visitParams(c);
  return c.values;
}

// The current lab's own defaults: a fresh instance's parameters (not set up).
static Settings labDefaults(std::string_view labId) {
  CollectAsText c;
  if (auto fresh = makeLab(labId)) fresh->visitParams(c);
  return std::move(c.values);
}

Settings LabHost::defaultSettings() {
  Settings defaults = labDefaults(lab_->id());
  for (const std::string& s : built_.scene.suggestedSettings) {
    const size_t eq = s.find('=');
    const std::string key = ownKey(s.substr(0, eq));
    for (auto& [k, v] : defaults)
      if (!key.empty() && k == key) v = s.substr(eq + 1);
  }
  return defaults;
}

void LabHost::resetParams() {
  lab_->resetParams();
  applySceneSettings({});
}

void LabHost::applySceneSettings(const std::vector<std::string>& leaving) {
  if (!leaving.empty()) {  // what the scene before suggested goes back to the lab's own default
    const Settings defaults = labDefaults(lab_->id());
    for (const std::string& s : leaving) {
      const std::string key = ownKey(s.substr(0, s.find('=')));
      for (const auto& [k, v] : defaults)
        if (!key.empty() && k == key) set(k + "=" + v);
    }
  }
  // A scene's suggestions are the project's own text: one that does not apply is a bug the lab
  // tests catch (every scene is selected there), not something a user can fix, so it is not shown.
  for (const std::string& s : built_.scene.suggestedSettings)
    if (!ownKey(s.substr(0, s.find('='))).empty()) set(s);
}

std::vector<gl::PassTiming> LabHost::draw(gl::PassTimer& timer, const gl::RenderTarget& target,
                                          const OrbitCamera& camera, float time, glm::vec2 jitter, int slice,
                                          int slices) {
  ensureScene();  // on failure the last good scene stays; warnings() tells why
  timer.beginFrame();
  target.bind();
  Frame frame{target, built_.scene, built_.gpu, camera, timer, time, jitter, slice, std::max(slices, 1)};
  lab_->render(frame);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  return timer.endFrame();
}

std::vector<gl::PassTiming> LabHost::drawInto(const gl::RenderTarget& target, const OrbitCamera& camera, float time,
                                              glm::vec2 jitter, int slice, int slices) {
  return draw(truthTimer_, target, camera, time, jitter, slice, slices);
}

void LabHost::traceFrame(const gl::RenderTarget& target, const OrbitCamera& camera, float time,
                         const std::function<void(Judge&, Frame&)>& begin) {
  ensureScene();
  truthTimer_.beginFrame();
  Frame frame{target, built_.scene, built_.gpu, camera, truthTimer_, time};
  if (Judge* judge = lab_->judge()) begin(*judge, frame);
  truthTimer_.endFrame();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  glUseProgram(0);
}

TraceWork LabHost::trace(const gl::RenderTarget& target, const OrbitCamera& camera, float time) {
  TraceWork work;
  traceFrame(target, camera, time, [&](Judge& judge, Frame& frame) { work = judge.traceReference(frame); });
  return work;
}

GlTraceStep LabHost::traceOnGl(const gl::RenderTarget& target, const OrbitCamera& camera, float time) {
  GlTraceStep step;
  traceFrame(target, camera, time, [&](Judge& judge, Frame& frame) { step = judge.traceReferenceOnGl(frame); });
  return step;
}

bool LabHost::pollChanges() {
  const bool rebuilt = shaders_->reloadChanged() > 0;
  return jobs_.deliver() > 0 || rebuilt;
}

const std::vector<gl::PassTiming>& LabHost::renderFrame(glm::ivec2 size, float time, float dt) {
  shaders_->reloadChanged();
  jobs_.deliver();
  for (auto& e : jobs_.takeErrors()) jobErrors_.push_back(std::move(e));
  ensureScene();
  if (!target_ || target_->size() != size) target_ = gl::RenderTarget::create(size);
  lab_->update(built_.scene, dt);
  draw(timer_, *target_, camera_, time, glm::vec2(0.0f));
  return timer_.lastFrame();
}

void LabHost::settle(const std::function<void(const std::vector<JobStatus>&)>& onProgress) {
  for (;;) {
    jobs_.deliver(1e9);
    ensureScene();
    lab_->update(built_.scene, 0.0f);  // submits what the current settings need, if anything
    if (!jobs_.busy()) break;
    jobs_.waitAll(onProgress);
  }
  for (auto& e : jobs_.takeErrors()) jobErrors_.push_back(std::move(e));
}

ImageF LabHost::renderMeasured(glm::ivec2 size, float time) {
  return renderView(size, time, lab_->judge() ? lab_->judge()->measuredView() : Settings{});
}

ImageF LabHost::renderView(glm::ivec2 size, float time, const Settings& view) {
  const Settings saved = currentSettings();
  applySettings(view);
  if (!sideTarget_ || sideTarget_->size() != size) sideTarget_ = gl::RenderTarget::create(size);
  drawInto(*sideTarget_, camera_, time);  // never into the view's target: the student sees no flash
  ImageF image{size, sideTarget_->readRgba()};
  applySettings(saved);
  return image;
}

ImageF LabHost::renderReference(glm::ivec2 size, float time) {
  return renderTruthNow(*this, describeTruth(*this, size, time));
}

std::vector<std::string> LabHost::warnings() const {
  std::vector<std::string> w = built_.warnings;
  for (auto& s : lab_->warnings()) w.push_back(s);
  for (auto& e : jobErrors_) w.push_back(e);
  return w;
}

nlohmann::json LabHost::stateJson() {
  nlohmann::json params = nlohmann::json::object();
  for (auto& [k, v] : currentSettings()) params[k] = v;
  nlohmann::json state = {{"lab", lab_->id()}, {"scene", sceneId_}, {"params", params}, {"camera", camera_.toString()}};
  if (!heightMap_.empty()) state["height_map"] = heightMap_;
  return state;
}

std::string LabHost::applyStateJson(const nlohmann::json& state) {
  Preset preset;
  if (auto err = parsePreset(state, preset); !err.empty()) return "preset: " + err;
  return applyPreset(preset);
}

std::string LabHost::applyPreset(const Preset& preset) {
  if (preset.lab && *preset.lab != lab_->id())
    if (auto err = selectLab(*preset.lab); !err.empty()) return err;
  if (preset.scene && *preset.scene != sceneId_)
    if (auto err = selectScene(*preset.scene); !err.empty()) return err;
  if (preset.heightMap && *preset.heightMap != heightMap_)
    if (auto err = setHeightMap(*preset.heightMap); !err.empty()) return "height_map: " + err;
  const Settings before = currentSettings();
  for (auto& [k, v] : preset.params)
    if (auto err = set(k + "=" + v); !err.empty()) {
      applySettings(before);  // all or nothing
      return "preset: " + err;
    }
  if (preset.camera)
    if (auto err = camera_.parse(*preset.camera); !err.empty()) return "preset: " + err;
  return {};
}

}  // namespace shadelab
