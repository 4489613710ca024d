#include "labs/filtering/filtering_lab.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "app/gl/driver_caveats.h"
#include "app/lab/technique.h"
#include "app/lab/variants.h"
#include "app/shader/preprocessor.h"
#include "labs/filtering/filtering_scenes.h"

namespace shadelab {
namespace {

// The techniques: a new filter is its row here, its branch in filter.glsl (under its define) and its test.
struct TexelFilterRow {
  TexelFilter value;
  std::string_view name;
  std::string_view define;
  bool inHardware;  // the sampler can do it; otherwise the shader filters
};
constexpr TexelFilterRow kTexelFilters[] = {
    {TexelFilter::Nearest, "nearest", "FILTER_NEAREST", true},
    {TexelFilter::Bilinear, "bilinear", "FILTER_BILINEAR", true},
    {TexelFilter::Bicubic, "bicubic", "FILTER_BICUBIC", false},
};
static_assert(coversEnum<TexelFilter>(kTexelFilters));

constexpr NamedDefine<MipSelection> kMipSelections[] = {
    {MipSelection::Off, "off", "MIP_NONE"},
    {MipSelection::NearestLevel, "nearest-level", "MIP_NEAREST"},
    {MipSelection::LinearLevel, "linear-level", "MIP_LINEAR"},
};
static_assert(coversEnum<MipSelection>(kMipSelections));

constexpr NamedDefine<FilteringView> kFilteringViews[] = {
    {FilteringView::Shaded, "shaded", "VIEW_SHADED"},
    {FilteringView::MipLevel, "mip-level", "VIEW_MIP_LEVEL"},
    {FilteringView::Anisotropy, "anisotropy", "VIEW_ANISOTROPY"},
};
static_assert(coversEnum<FilteringView>(kFilteringViews));

constexpr Named<MipBuilder> kBuilders[] = {
    {MipBuilder::Box, "box"}, {MipBuilder::Kaiser, "kaiser"}, {MipBuilder::Driver, "driver"}};
static_assert(coversEnum<MipBuilder>(kBuilders));
constexpr Named<PixelFilter> kPixelFilters[] = {{PixelFilter::Box, "box"}, {PixelFilter::Gaussian, "gaussian"}};
static_assert(coversEnum<PixelFilter>(kPixelFilters));

constexpr int kUnit = 0;

// The standard deviation of a level's luminance (linear light): how much detail it still holds.
float luminanceContrast(const LinearImage& image) {
  double sum = 0.0, sq = 0.0;
  for (const glm::vec4& t : image.texels) {
    const double l = 0.2126 * t.r + 0.7152 * t.g + 0.0722 * t.b;
    sum += l;
    sq += l * l;
  }
  const double n = double(std::max<size_t>(image.texels.size(), 1));
  const double mean = sum / n;
  return float(std::sqrt(std::max(sq / n - mean * mean, 0.0)));
}

}  // namespace

std::string_view FilteringLab::summary() const {
  return "A ground plane to the horizon: near, one texel covers many pixels (magnification); far, one pixel covers "
         "hundreds of texels (minification). Nearest sparkles, bilinear aliases in the distance, mipmaps trade the "
         "aliasing for blur, trilinear hides the seams between levels, anisotropic filtering takes several probes "
         "along the footprint and keeps the detail. Every filter is measured against each pixel's footprint "
         "integrated by 16 x 16 samples, and by how much it flickers while the camera creeps forward.";
}

std::vector<SceneRecipe> FilteringLab::scenes() const { return filteringScenes(); }

void FilteringLab::visitParams(ParamVisitor& v) {
  auto& p = params;
  v.section("Filter");
  v.enumParam({"filter", "Within a level", "",
               "nearest: the texel the sample falls in; bilinear: the four nearest "
               "texels, two lerps and a third; bicubic: sixteen texels with Catmull-Rom weights (written in the shader "
               "only: hardware has no bicubic filter)."},
              p.filter, namesOf<kTexelFilters>());
  v.enumParam({"mipmaps", "Mip levels", "",
               "off: always level 0 (minification aliases); nearest-level: the level "
               "closest to L = log2(footprint in texels); linear-level: a blend of the two levels around L "
               "(with bilinear: trilinear filtering)."},
              p.mipmaps, namesOf<kMipSelections>());
  v.boolParam({"in_shader", "Written in the shader", "",
               "Filter with texelFetch and arithmetic (filter.glsl) instead "
               "of the texture unit: the same filter, made visible and editable."},
              p.inShader);
  if (anisotropyLimit_ > 0.0f && anisotropyLimit_ <= 1.0f && !p.inShader)
    v.unavailable(
        "this driver has no anisotropic filtering (EXT_texture_filter_anisotropic); tick 'Written in the "
        "shader' to use the shader's version");
  else if (p.mipmaps == MipSelection::Off)
    v.unavailable(
        "the probes read smaller mip levels: with mip levels off there are none, so anisotropy is left out "
        "(llvmpipe would spend ~15x the time on it for the same picture)");
  v.intParam({"anisotropy", "Anisotropy", "x",
              "Up to this many probes along the footprint's long axis, each at the "
              "level of the footprint's width over their number (needs mip levels)."},
             p.anisotropy, 1, 16);
  v.floatParam({"lod_bias", "LOD bias", "levels",
                "Added to L: positive reads smaller levels (blur), negative larger "
                "ones (aliasing). Hardware clamps it to the driver's limit."},
               p.lodBias, -16.0f, 16.0f);
  v.boolParam({"manual_level", "Choose the level", "", "Read one level everywhere, ignoring the footprint."},
              p.manualLevel);
  v.floatParam({"level", "Level", "",
                "The level read when it is chosen by hand (fractions blend two levels with "
                "linear-level)."},
               p.level, 0.0f, 14.0f);
  v.section("Mip chain");
  v.enumParam({"downsampler", "Made by", "",
               "box: each texel the mean of the texels it covers (in linear light, exact "
               "for odd sizes); kaiser: a Kaiser-windowed sinc 3 texels wide (alpha 4), sharper levels; driver: "
               "glGenerateMipmap, whatever the driver does."},
              p.builder, namesOf<kBuilders>());
  v.section("View");
  v.enumParam({"view", "View", "",
               "shaded; mip-level: the level read, one colour per level (red 0, orange 1, yellow 2, "
               "green 3, cyan 4, blue 5, violet 6, pink 7, then again), blended for trilinear; anisotropy: the "
               "footprint's length over its width, slate 1x to yellow 16x."},
              p.view, namesOf<kFilteringViews>());
  v.boolParam({"footprint_probe", "Footprint probe", "",
               "Read one pixel's footprint back from the GPU and draw it in "
               "texel space (the Footprint panel); the pixel is marked with a ring."},
              p.probe);
  v.floatParam({"probe_x", "Probe x", "", "The probe pixel across the frame, 0 left .. 1 right."}, p.probeX, 0.0f,
               1.0f);
  v.floatParam({"probe_y", "Probe y", "", "The probe pixel down the frame, 0 top .. 1 bottom."}, p.probeY, 0.0f, 1.0f);
  v.section("Measure");
  v.enumParam({"pixel_filter", "Reference pixel filter", "",
               "How the truth weighs its 16 x 16 samples over a pixel: box "
               "(the pixel's square) or gaussian (sigma 0.5 px over 3 x 3 px: softer, less ringing)."},
              p.pixelFilter, namesOf<kPixelFilters>());
  v.intParam({"motion_frame", "Motion frame", "",
              "Frame of the slow forward move that flicker is measured over "
              "(each moves the camera 0.4 % of its distance)."},
             p.motionFrame, 0, 30);
  v.boolParam({"animate", "Animate", "",
               "Move the camera slowly back and forth (window only): watch the distance "
               "shimmer."},
              p.animate);
}

bool FilteringLab::inShader() const {
  return params.inShader || !rowOf(kTexelFilters, params.filter).inHardware || anisotropyMovedToShader();
}

bool FilteringLab::anisotropyMovedToShader() const {
  return slowDriverAnisotropy_ && !params.inShader && rowOf(kTexelFilters, params.filter).inHardware &&
         anisotropy() > 1 && (params.manualLevel || params.lodBias < 0.0f);
}

SceneNeeds FilteringLab::needs() const {
  SceneNeeds n;
  n.uvs = true;
  n.baseColorTextures = false;  // the lab decodes and builds its own chains, for the images it draws
  n.mipmaps = false;
  return n;
}

ProgramSpec FilteringLab::programSpec(const FilteringParams& p, bool probePass) const {
  ProgramSpec spec;
  spec.stages = {{GL_VERTEX_SHADER, "filtering/filtering.vert"}, {GL_FRAGMENT_SHADER, "filtering/filtering.frag"}};
  auto define = [&](std::string_view name) { spec.defines.emplace_back(name, "1"); };
  if (probePass) {
    spec.name = "filtering/footprint probe";
    define("PROBE");
    define("MIP_NONE");
    return spec;
  }
  const TexelFilterRow& filter = rowOf(kTexelFilters, p.filter);
  const NamedDefine<MipSelection>& mips = rowOf(kMipSelections, p.mipmaps);
  const bool shader = p.inShader || !filter.inHardware;
  spec.name = "filtering/" + std::string(filter.name) + " " + std::string(mips.name) + (shader ? " (shader)" : "");
  define(filter.define);
  define(mips.define);
  define(rowOf(kFilteringViews, p.view).define);
  if (shader) define("IN_SHADER");
  if (p.manualLevel) define("MANUAL_LEVEL");
  if (p.probe) define("PROBE_MARKER");
  return spec;
}

// A pairwise cover of the choices the shader is compiled for: every value, and every pair of
// values, of filter, mip selection, in-shader filtering, view, manual level and probe marker in some
// program (the test that random settings draw nothing else: gl/lab_lifecycle_test.cpp).
std::vector<ProgramSpec> FilteringLab::allPrograms() const {
  std::vector<ProgramSpec> all = {programSpec(FilteringParams{}, true)};
  for (const auto& row :
       pairwiseCover({int(TexelFilter::Count), int(MipSelection::Count), 2, int(FilteringView::Count), 2, 2})) {
    FilteringParams p;
    p.filter = TexelFilter(row[0]);
    p.mipmaps = MipSelection(row[1]);
    p.inShader = row[2] == 1;
    p.view = FilteringView(row[3]);
    p.manualLevel = row[4] == 1;
    p.probe = row[5] == 1;
    all.push_back(programSpec(p, false));
  }
  // One of each: rows that differ only in what the program ignores compile the same program.
  std::set<std::string> seen;
  std::erase_if(all, [&](const ProgramSpec& spec) { return !seen.insert(spec.key()).second; });
  return all;
}

std::string FilteringLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  sampler_ = gl::Sampler::make();
  makeTexelSampler();
  probeTarget_ = gl::RenderTarget::create({2, 2}, GL_RGBA32F);
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &maxBias_);
  anisotropyLimit_ = gl::maxAnisotropy();
  slowDriverAnisotropy_ = gl::applies(gl::Caveat::SlowAnisotropy);
  const uint8_t white[4] = {255, 255, 255, 255};
  gl::SamplerState s;
  s.minFilter = s.magFilter = GL_NEAREST;
  white_ = gl::Texture2D::fromRgba8({1, 1}, white, s, true);
  return {};
}

const FilteringLab::ChainTexture* FilteringLab::chain(const Scene& scene, int image) {
  for (const ChainTexture& c : chains_)
    if (c.image == image && c.builder == params.builder) return &c;
  if (image < 0 || size_t(image) >= scene.images.size()) return nullptr;
  auto& level0 = decoded_[size_t(image)];
  if (!level0) {
    std::vector<uint8_t> rgba;
    glm::ivec2 size;
    if (auto err = decodeImage(scene.images[size_t(image)], rgba, size); !err.empty()) {
      frameNotes_.push_back(err + "; drawn untextured");
      return nullptr;
    }
    level0 = decodeSrgb8(size, flipRows(rgba, size, 4));  // kept in GL's row order: no flip at upload
    ++imagesDecoded_;
  }
  ChainTexture c;
  c.image = image;
  c.builder = params.builder;
  const glm::ivec2 size = level0->size;
  c.levels = mipLevelCount(size);
  c.texture = gl::Texture2D::allocate(size, GL_SRGB8_ALPHA8, c.levels);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::vector<uint8_t>> levels;  // sRGB8, GL's row order
  if (params.builder == MipBuilder::Driver) {
    levels.push_back(encodeSrgb8(*level0));
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, levels[0].data());
    glGenerateMipmap(GL_TEXTURE_2D);
    for (int l = 1; l < c.levels; ++l) {
      const glm::ivec2 s = mipLevelSize(size, l);
      levels.emplace_back(size_t(s.x) * size_t(s.y) * 4);
      glGetTexImage(GL_TEXTURE_2D, l, GL_RGBA, GL_UNSIGNED_BYTE, levels.back().data());
    }
  } else {
    const auto chainLevels =
        buildMipChain(*level0, params.builder == MipBuilder::Box ? MipDownsampler::Box : MipDownsampler::Kaiser);
    for (int l = 0; l < c.levels; ++l) {
      levels.push_back(encodeSrgb8(chainLevels[size_t(l)]));
      const glm::ivec2 s = chainLevels[size_t(l)].size;
      glTexSubImage2D(GL_TEXTURE_2D, l, 0, 0, s.x, s.y, GL_RGBA, GL_UNSIGNED_BYTE, levels.back().data());
    }
  }
  // Statistics of the levels as stored (8-bit), and the chain side by side: level 0 on the left,
  // the others stacked on its right.
  glm::ivec2 atlasSize(size.x + (c.levels > 1 ? mipLevelSize(size, 1).x : 0), size.y);
  int stack = 0;
  for (int l = 1; l < c.levels; ++l) stack += mipLevelSize(size, l).y + 2;
  atlasSize.y = std::max(atlasSize.y, stack);
  atlasSize.x += 2;
  std::vector<uint8_t> atlas(size_t(atlasSize.x) * size_t(atlasSize.y) * 4, 40);
  int y0 = atlasSize.y;  // levels 1.. from the top down (GL rows run bottom-up)
  for (int l = 0; l < c.levels; ++l) {
    const glm::ivec2 s = mipLevelSize(size, l);
    c.sizes.push_back(s);
    c.contrast.push_back(luminanceContrast(decodeSrgb8(s, levels[size_t(l)])));
    const int x = l == 0 ? 0 : size.x + 2;
    const int y = l == 0 ? atlasSize.y - s.y : (y0 -= s.y + (l == 1 ? 0 : 2));
    for (int row = 0; row < s.y; ++row)
      std::copy_n(levels[size_t(l)].begin() + ptrdiff_t(size_t(row) * size_t(s.x) * 4), size_t(s.x) * 4,
                  atlas.begin() + ptrdiff_t((size_t(y + row) * size_t(atlasSize.x) + size_t(x)) * 4));
  }
  gl::SamplerState as;
  as.wrapS = as.wrapT = GL_CLAMP_TO_EDGE;
  c.atlas = gl::Texture2D::fromRgba8(atlasSize, atlas.data(), as, true);
  chains_.push_back(std::move(c));
  return &chains_.back();
}

void FilteringLab::applySampler() {
  const GLuint s = sampler_.get();
  static const GLenum minFilter[2][3] = {{GL_NEAREST, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR},
                                         {GL_LINEAR, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR}};
  const bool nearest = params.filter == TexelFilter::Nearest;
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GLint(minFilter[nearest ? 0 : 1][int(params.mipmaps)]));
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_REPEAT);
  // GLSL ES has no sampler LOD bias: there the shader passes the same bias to texture() (SHADELAB_ES).
  if (glslDialect() == GlslDialect::Desktop)
    glSamplerParameterf(s, GL_TEXTURE_LOD_BIAS, std::clamp(params.lodBias, -maxBias_, maxBias_));
  if (anisotropyLimit_ > 1.0f)
    glSamplerParameterf(s, GL_TEXTURE_MAX_ANISOTROPY, std::clamp(float(anisotropy()), 1.0f, anisotropyLimit_));
}

// What filter.glsl reads texels through: one texel of one level, nothing blended.
void FilteringLab::makeTexelSampler() {
  texelSampler_ = gl::Sampler::make();
  const GLuint s = texelSampler_.get();
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

// The camera, moved forward along its view by the slow motion flicker is measured over.
glm::mat4 FilteringLab::viewMatrix(const Frame& frame) const {
  const glm::vec3 eye = frame.camera.eye();
  const glm::vec3 forward = glm::normalize(frame.camera.target - eye);
  float offset = 0.004f * float(params.motionFrame);
  if (params.animate) offset += 0.05f * std::sin(0.6f * frame.time);
  return frame.camera.view() * glm::translate(glm::mat4(1.0f), -forward * offset * frame.camera.distance);
}

void FilteringLab::render(Frame& frame) {
  frameNotes_.clear();
  if (sceneRevision_ != frame.scene.revision) {
    chains_.clear();
    decoded_.assign(frame.scene.images.size(), std::nullopt);
    sceneRevision_ = frame.scene.revision;
  }
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(0.55f, 0.68f, 0.82f, 0.0f);  // sky; alpha 0: not covered, left out of the error
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  applySampler();
  const glm::mat4 viewProj = frame.projection() * viewMatrix(frame);
  shown_ = -1;
  Program& prog = program_.get(*shaders_, programSpec(params, false));
  {
    auto pass = frame.pass(std::string("texture: ") + std::string(rowOf(kTexelFilters, params.filter).name) + ", mip " +
                           std::string(rowOf(kMipSelections, params.mipmaps).name) + (inShader() ? ", in shader" : "") +
                           (anisotropy() > 1 ? ", " + std::to_string(anisotropy()) + "x" : ""));
    prog.use();
    prog.set("u_viewProj", viewProj);
    prog.set("u_map", kUnit);
    prog.set("u_lodBias", params.lodBias);  // the ES path's texture() bias is clamped as the sampler's is
    prog.set("u_level", params.level);
    prog.set("u_maxAnisotropy",
             inShader() ? float(anisotropy()) : std::min(float(anisotropy()), std::max(anisotropyLimit_, 1.0f)));
    const glm::ivec2 probe = probePixel(frame.size());  // from the top-left; gl_FragCoord counts from the bottom
    prog.set("u_probe", glm::vec2(float(probe.x) + 0.5f, float(frame.size().y - 1 - probe.y) + 0.5f));
    for (const Instance& inst : frame.scene.instances) {
      const MeshData& mesh = frame.scene.meshes[size_t(inst.mesh)];
      const Material& mat = frame.scene.materials[size_t(std::max(mesh.material, 0))];
      const ChainTexture* tex = mesh.uvs.empty() ? nullptr : chain(frame.scene, mat.baseColorImage);
      if (tex && shown_ < 0) shown_ = int(tex - chains_.data());
      (tex ? tex->texture : white_).bind(kUnit);
      glBindSampler(kUnit, inShader() ? texelSampler_.get() : sampler_.get());
      prog.set("u_maxLevel", tex ? tex->levels - 1 : 0);
      prog.set("u_baseColor", mat.baseColor);
      prog.set("u_model", inst.model);
      frame.gpu.draw(inst);
    }
    glBindSampler(kUnit, 0);
  }
  if (params.probe) probeFootprint(frame, viewProj);
}

glm::ivec2 FilteringLab::probePixel(glm::ivec2 size) const {
  return {int(std::floor(params.probeX * float(size.x - 1))), int(std::floor(params.probeY * float(size.y - 1)))};
}

// One pixel's footprint: the probe program draws the scene into a 2 x 2 target whose viewport
// is shifted so that the probe pixel lands on its corner (derivatives need the 2 x 2 quad).
void FilteringLab::probeFootprint(Frame& frame, const glm::mat4& viewProj) {
  auto pass = frame.pass("footprint probe");
  const glm::ivec2 size = frame.size();
  const glm::ivec2 px = probePixel(size);
  const int glY = size.y - 1 - px.y;
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  probeTarget_.bind();
  glViewport(-(px.x & ~1), -(glY & ~1), size.x, size.y);  // the quad containing the pixel
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  Program& prog = probeProgram_.get(*shaders_, programSpec(params, true));
  prog.use();
  prog.set("u_viewProj", viewProj);
  prog.set("u_map", kUnit);
  for (const Instance& inst : frame.scene.instances) {
    const MeshData& mesh = frame.scene.meshes[size_t(inst.mesh)];
    const Material& mat = frame.scene.materials[size_t(std::max(mesh.material, 0))];
    const ChainTexture* tex = mesh.uvs.empty() ? nullptr : chain(frame.scene, mat.baseColorImage);
    (tex ? tex->texture : white_).bind(kUnit);
    prog.set("u_model", inst.model);
    prog.set("u_maxLevel", 0);
    frame.gpu.draw(inst);
  }
  float texel[4] = {0, 0, 0, 0};
  glBindFramebuffer(GL_READ_FRAMEBUFFER, probeTarget_.fbo());
  glReadPixels(px.x & 1, glY & 1, 1, 1, GL_RGBA, GL_FLOAT, texel);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  glViewport(0, 0, size.x, size.y);
  footprint_.pixel = px;
  footprint_.dx = {texel[0], texel[1]};
  footprint_.dy = {texel[2], texel[3]};
  footprint_.covered = texel[0] != 0.0f || texel[1] != 0.0f || texel[2] != 0.0f || texel[3] != 0.0f;
}

std::vector<ProgramRef> FilteringLab::activePrograms() const {
  std::vector<ProgramRef> out;
  if (program_.current()) out.push_back(program_.current());
  if (params.probe && probeProgram_.current()) out.push_back(probeProgram_.current());
  return out;
}

}  // namespace shadelab
