// The shading lab measured against its reference (per-fragment Phong on the finest mesh).
#include <gtest/gtest.h>

#include <fstream>

#include "gl_test.h"

using namespace shadelab;

static double errorOf(LabHost& host, const std::vector<std::string>& sets, const ImageF& reference) {
  for (auto& s : sets) EXPECT_EQ(host.set(s), "");
  host.renderFrame(reference.size);
  // Surface error: the silhouette of a coarse mesh is the same for every mode and would hide them.
  return compareImages(host.readImage(), reference).coveredRmse;
}

TEST(ShadingReference, ErrorOrdersByFrequencyAndFallsWithTessellation) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectScene("sphere"), "");
  const ImageF ref = host.renderReference({192, 192});
  ASSERT_EQ(countNonFinite(ref), 0u);
  const double flat = errorOf(host, {"shading.mode=flat", "shading.tessellation=16"}, ref);
  const double gouraud = errorOf(host, {"shading.mode=gouraud"}, ref);
  const double phong = errorOf(host, {"shading.mode=phong"}, ref);
  EXPECT_GT(flat, gouraud);
  EXPECT_GT(gouraud, phong);
  const double phongFine = errorOf(host, {"shading.tessellation=128"}, ref);
  EXPECT_LT(phongFine, phong);
  EXPECT_LT(phongFine, 0.005);  // only the tessellation differs from the reference now
  const double flatFine = errorOf(host, {"shading.mode=flat", "shading.tessellation=128"}, ref);
  EXPECT_LT(flatFine, flat);
}

TEST(ShadingReference, AffineUvsAreWrongOnlyUnderPerspective) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectScene("checker-plane"), "");
  ASSERT_EQ(host.set("shading.mode=phong"), "");
  host.renderFrame({192, 108});
  const ImageF correct = host.readImage();
  ASSERT_EQ(host.set("shading.uv_interpolation=affine"), "");
  host.renderFrame({192, 108});
  EXPECT_GT(compareImages(host.readImage(), correct).badPixelPct, 5.0);  // bent checker lines
  // Seen straight down, w is constant across the floor: affine equals perspective-correct.
  ASSERT_EQ(host.camera().parse("pitch=89.9,yaw=0"), "");
  host.set("shading.uv_interpolation=perspective");
  host.renderFrame({192, 108});
  const ImageF top = host.readImage();
  host.set("shading.uv_interpolation=affine");
  host.renderFrame({192, 108});
  EXPECT_LT(compareImages(host.readImage(), top).badPixelPct, 0.5);
}

namespace {

// A 2 x 2 quad at height 0 split into two triangles, the second wound the other way (as files
// stitched from several sources often are); every vertex normal points up. `scale` shrinks it.
std::string mixedWindingQuad(const std::string& name, float scale) {
  const std::string path = test::testOutput(name).string();
  std::ofstream f(path);
  for (auto [x, z] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}})
    f << "v " << x * scale << " 0 " << z * scale << "\n";
  f << "vn 0 1 0\n";
  f << "f 1//1 4//1 3//1\n";  // counter-clockwise seen from above
  f << "f 1//1 2//1 3//1\n";  // clockwise seen from above
  return path;
}

// The mean green of the image's left and right halves' centres (one triangle each, seen from above).
std::pair<double, double> halves(const ImageF& img) {
  double sum[2] = {0, 0};
  int n[2] = {0, 0};
  for (int y = img.size.y / 4; y < img.size.y * 3 / 4; ++y)
    for (int x = img.size.x / 8; x < img.size.x * 7 / 8; ++x) {
      const bool right = x > img.size.x / 2;
      if (std::abs(x - img.size.x / 2) < img.size.x / 16) continue;  // keep off the diagonal
      sum[right] += img.at(x, y)[1];
      ++n[right];
    }
  return {sum[0] / std::max(n[0], 1), sum[1] / std::max(n[1], 1)};
}

ImageF shadedFromAbove(LabHost& host) {
  host.renderFrame({64, 64});  // builds the scene and frames the camera
  EXPECT_EQ(host.camera().parse("yaw=0,pitch=89,fov=30"), "");
  host.camera().distance = 2.8f * host.scene().bounds.radius();  // the quad fills the middle, at any scale
  host.camera().target = host.scene().bounds.center();
  host.camera().fitDepthRange(host.scene().bounds.center(), host.scene().bounds.radius());
  const gl::RenderTarget target = gl::RenderTarget::create({128, 128});
  host.drawInto(target, host.camera(), 0.0f);
  return ImageF{{128, 128}, target.readRgba()};
}

}  // namespace

// Flat shading takes the face normal from the winding; a triangle wound the other way must still
// face the way its vertex normals say, and every mode lights the side the eye sees.
TEST(Shading, MixedWindingShadesAlikeInEveryMode) {
  const std::string path = mixedWindingQuad("mixed_winding.obj", 1.0f);
  for (const char* mode : {"flat", "gouraud", "phong"}) {
    auto host = test::labHost("shading", path.c_str(), {std::string("shading.mode=") + mode, "shading.ks=0"});
    const auto [left, right] = halves(shadedFromAbove(*host));
    EXPECT_GT(left, 0.1) << mode;
    EXPECT_NEAR(right / left, 1.0, 0.15) << mode << ": one triangle of the quad shades differently";
  }
}

// Flat shading without a geometry shader (WebGL2's way): unwelded faces lit in the vertex stage
// draw the geometry shader's picture, on mixed winding, on degenerate poles (tessellation 3) and
// on the lab's scene with textures and four lights.
TEST(Shading, UnweldedFacesDrawWhatTheGeometryShaderDraws) {
  const std::string mixed = mixedWindingQuad("mixed_winding_flat.obj", 1.0f);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"shading", {"shading.lights=4", "shading.ks=0.8"}},
      {"sphere", {"shading.tessellation=3"}},
      {mixed, {}},
  };
  for (auto& [scene, sets] : cases) {
    ImageF frames[2];
    for (int unwelded = 0; unwelded < 2; ++unwelded) {
      std::vector<std::string> all = sets;
      all.push_back("shading.mode=flat");
      all.push_back(std::string("shading.flat_faces=") + (unwelded ? "unwelded" : "geometry_shader"));
      auto host = test::labHost("shading", scene.c_str(), all);
      host->renderFrame({320, 240});
      frames[unwelded] = host->readImage();
      EXPECT_EQ(countNonFinite(frames[unwelded]), 0u) << scene;
    }
    const ImageError e = compareImages(frames[1], frames[0]);
    EXPECT_LT(e.rmse, 0.002) << scene;
    EXPECT_LT(e.badPixelPct, 0.05) << scene;  // a face's colour, not an edge pixel or two, would differ
  }
}

// The inverse-square falloff's floor on r^2 scales with the scene: a scene a thousandth the size
// (lights a thousandth as far) is lit exactly as brightly.
TEST(Shading, TinyScenesAreLitLikeLargeOnes) {
  auto big = test::labHost("shading", mixedWindingQuad("quad_1.obj", 1.0f).c_str(), {"shading.mode=phong"});
  auto tiny = test::labHost("shading", mixedWindingQuad("quad_1e-3.obj", 1e-3f).c_str(), {"shading.mode=phong"});
  const double a = halves(shadedFromAbove(*big)).first, b = halves(shadedFromAbove(*tiny)).first;
  EXPECT_GT(a, 0.1);
  EXPECT_NEAR(b / a, 1.0, 0.05);
}

// A student's lighting file changes the frame, never the truth it is judged against: truth frames
// are drawn with the built-in shaders, the student's frame right after with theirs.
TEST(ShadingReference, TheTruthIsDrawnWithTheBuiltInShadersWhateverTheStudentOverrides) {
  const std::filesystem::path starter =
      std::filesystem::path(SHADELAB_SOURCE_DIR) / "exercises/shading/blinn-phong/starter";
  LabHost builtin(test::builtinShaders());
  LabHost student(ShaderSearchPath({starter, std::filesystem::path(SHADELAB_SOURCE_DIR) / "shaders"}));
  for (LabHost* host : {&builtin, &student}) {
    ASSERT_EQ(host->selectScene("sphere"), "");
    ASSERT_EQ(host->set("shading.ks=0.8"), "");
  }
  const ImageF truth = builtin.renderReference({128, 128});
  EXPECT_EQ(compareImages(student.renderReference({128, 128}), truth).maxError, 0.0);
  builtin.renderFrame({128, 128});
  student.renderFrame({128, 128});
  EXPECT_GT(compareImages(student.readImage(), builtin.readImage()).coveredRmse, 0.01)
      << "the starter has no highlight";
}
