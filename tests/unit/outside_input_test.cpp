// Files handed in by other people reach nothing outside where they should: a glTF's buffers and
// an OBJ's material libraries and textures come only from the model's own folder; a preset is
// checked field by field before anything is applied; a rubric's files stay inside a shader folder.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "app/grade/rubric.h"
#include "app/host/preset.h"
#include "app/scene/loaders.h"
#include "app/util/contained_path.h"
#include "app/util/zip_writer.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

class OutsideInput : public ::testing::Test {
 protected:
  void SetUp() override {
    base = fs::temp_directory_path() / ("shadelab_outside_" + std::to_string(::getpid()));
    fs::remove_all(base);
    model = base / "downloads" / "model";
    fs::create_directories(model);
    fs::create_directories(base / "private");
  }
  void TearDown() override { fs::remove_all(base); }
  static void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
  }
  // A one-triangle glTF whose buffer is `uri`; the 36 bytes it needs are written to `bufferFile`.
  fs::path gltfWithBuffer(const std::string& uri, const fs::path& bufferFile) {
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write(bufferFile, std::string(reinterpret_cast<const char*>(xyz), sizeof xyz));
    const fs::path file = model / "tri.gltf";
    write(file, R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "buffers": [{"byteLength": 36, "uri": ")" +
                    uri + R"("}]})");
    return file;
  }
  fs::path base, model;
};

TEST_F(OutsideInput, GltfReadsItsOwnBuffer) {
  Scene s;
  EXPECT_EQ(loadSceneFile(gltfWithBuffer("tri.bin", model / "tri.bin"), s), "");
  ASSERT_EQ(s.meshes.size(), 1u);
}

TEST_F(OutsideInput, GltfBufferOutsideItsFolderIsNotRead) {
  for (const std::string& uri :
       std::vector<std::string>{"../../private/secret.bin", (base / "private" / "secret.bin").string()}) {
    Scene s;
    const std::string err = loadSceneFile(gltfWithBuffer(uri, base / "private" / "secret.bin"), s);
    EXPECT_NE(err, "") << uri;
    EXPECT_TRUE(s.meshes.empty()) << uri;
  }
  Scene s;
  fs::create_symlink(base / "private" / "secret.bin", model / "linked.bin");
  EXPECT_NE(loadSceneFile(gltfWithBuffer("linked.bin", base / "private" / "secret.bin"), s), "");
  EXPECT_TRUE(s.meshes.empty());
}

TEST_F(OutsideInput, ObjMaterialLibraryAndTexturesOutsideItsFolderAreNotRead) {
  write(base / "private" / "secret.mtl", "newmtl stolen\nKd 1 0 0\nmap_Kd secret.png\n");
  write(model / "own.mtl", "newmtl own\nKd 0 1 0\nmap_Kd ../../private/secret.png\n");
  write(model / "m.obj",
        "mtllib ../../private/secret.mtl\nmtllib own.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl own\nf 1 2 3\n");
  Scene s;
  ASSERT_EQ(loadSceneFile(model / "m.obj", s), "");
  for (auto& m : s.materials) EXPECT_NE(m.name, "stolen");
  bool ownRead = false;
  for (auto& m : s.materials) ownRead |= m.name == "own";
  EXPECT_TRUE(ownRead);
  for (auto& img : s.images) EXPECT_TRUE(img.file.empty()) << img.file;
  std::string warnings;
  for (auto& w : s.warnings) warnings += w;
  EXPECT_NE(warnings.find("is not a file in the OBJ's folder"), std::string::npos) << warnings;
}

TEST(Presets, EveryFieldIsCheckedBeforeAnythingIsApplied) {
  Preset p;
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"lab": "shading", "params": {"mode": "flat", "tessellation": 12,
      "textures": true}, "camera": "yaw=10", "size": [640, 480], "time": 2.5})"),
                        p),
            "");
  EXPECT_EQ(*p.lab, "shading");
  ASSERT_EQ(p.params.size(), 3u);
  EXPECT_EQ(p.params[2], (std::pair<std::string, std::string>("textures", "true")));
  EXPECT_EQ(*p.size, glm::ivec2(640, 480));
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"lab": 3})"), p), "'lab' must be a string");
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"height_map": ["a.png"]})"), p), "'height_map' must be a string");
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"height_map": "bumps.png"})"), p), "");
  EXPECT_EQ(p.heightMap, std::optional<std::string>("bumps.png"));
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"params": [1]})"), p), "'params' must be an object of key: value");
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"params": {"mode": {"a": 1}}})"), p),
            "params.mode: must be a number, a string or true/false");
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"time": 1e300})"), p),
            "'time' must be a number of seconds in [-1e6, 1e6]");
  EXPECT_EQ(parsePreset(nlohmann::json::parse(R"({"size": [1e300, -5]})"), p), "");
  EXPECT_EQ(*p.size, glm::ivec2(16384, 16)) << "sizes are clamped, never cast out of range";
  EXPECT_EQ(parsePreset(nlohmann::json::parse("[]"), p), "expected a JSON object with lab, scene, params, camera");
}

TEST(Presets, OnlyRegularFilesOfModestSizeAreRead) {
  Preset p;
  EXPECT_EQ(readPreset("/dev/zero", p), "/dev/zero: cannot open preset (not a file)");
  const fs::path big = fs::temp_directory_path() / ("shadelab_big_preset_" + std::to_string(::getpid()) + ".json");
  std::ofstream(big) << "{\"lab\": \"" << std::string(kMaxPresetBytes, 'x') << "\"}";
  EXPECT_NE(readPreset(big, p).find("too large for a preset"), std::string::npos);
  fs::remove(big);
}

TEST(ContainedPath, NamesThatLeaveAFolderAreEmpty) {
  EXPECT_EQ(containedName("a/./b/../c.glsl"), fs::path("a/c.glsl"));
  for (const char* bad : {"", "/abs", "..", "../x", "a/../../x", "./../x"})
    EXPECT_TRUE(containedName(bad).empty()) << bad;
  EXPECT_TRUE(containedName(std::string_view("a\0b", 3)).empty());
}

TEST(Grade, ARubricsFilesStayInsideAShaderFolder) {
  const fs::path root = fs::temp_directory_path() / ("shadelab-rubric-files-" + std::to_string(::getpid()));
  fs::remove_all(root);
  for (const char* file : {"../../etc/passwd", "/etc/passwd", "common/../../x.glsl"}) {
    fs::create_directories(root / "shading" / "bad");
    std::ofstream(root / "shading" / "bad" / "rubric.json")
        << R"({"title": "t", "lab": "shading", "files": [")" << file << R"("], "configurations": [
               {"name": "a", "checks": [{"name": "x", "metric": "rmse", "against": "solution", "full": 1}]}]})";
    Exercise ex;
    const std::string err = loadExercise(root, "shading/bad", ex);
    EXPECT_NE(err.find("\"files\" must hold paths relative to a shader folder"), std::string::npos)
        << file << ": " << err;
  }
  fs::remove_all(root);
}

TEST(Grade, ARubricsVisibilityIsOneGradebooksKnow) {
  const fs::path root = fs::temp_directory_path() / ("shadelab-rubric-visibility-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "shading" / "seen");
  for (const char* visibility : {"hidden", "secret"}) {
    std::ofstream(root / "shading" / "seen" / "rubric.json")
        << R"({"title": "t", "lab": "shading", "files": ["common/specular.glsl"], "configurations": [
               {"name": "a", "visibility": ")"
        << visibility << R"(", "checks": [{"name": "x", "metric": "rmse", "against": "solution", "full": 1}]}]})";
    Exercise ex;
    const std::string err = loadExercise(root, "shading/seen", ex);
    if (std::string(visibility) == "hidden") {
      ASSERT_EQ(err, "");
      EXPECT_EQ(ex.configurations.at(0).visibility, "hidden");
    } else {
      EXPECT_NE(err.find("\"visibility\" must be visible, hidden, after_due_date or after_published"),
                std::string::npos)
          << err;
    }
  }
  fs::remove_all(root);
}

}  // namespace

namespace {

TEST(Loaders, PlyValuesPastFloatOrNotFiniteNeverReachTheMesh) {
  const fs::path dir = fs::path(SHADELAB_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / "ply";
  Scene s;
  // A normal of 1e300 (a double past float's range): normals are computed from the face instead.
  ASSERT_EQ(loadSceneFile(dir / "double-past-float.ply", s), "");
  for (auto& n : s.meshes.at(0).normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings[0].find("normals computed from the faces"), std::string::npos) << s.warnings[0];
  // An element of no properties and 2^64-1 entries reads nothing and ends at once.
  Scene t;
  EXPECT_EQ(loadSceneFile(dir / "empty-element-huge-count.ply", t), "");
}

}  // namespace

// What the in-app editor's "Download my shaders" writes: a stored zip. Its checksum is the one
// every unzip tool checks; tests/grade/class_test.cpp reads the archive back with libzip.
TEST(ZipWriter, TheChecksumIsZipsCrc32AndTheArchiveEndsWithItsDirectory) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);  // the CRC-32 check value
  EXPECT_EQ(crc32(""), 0u);
  const std::string zip = storedZip({{"shadows/pcf.glsl", "// mine\n"}, {"common/lighting.glsl", ""}});
  ASSERT_GE(zip.size(), 22u);
  EXPECT_EQ(zip.substr(0, 4), std::string("PK\x03\x04", 4));
  const std::string end = zip.substr(zip.size() - 22);
  EXPECT_EQ(end.substr(0, 4), std::string("PK\x05\x06", 4));
  EXPECT_EQ(uint8_t(end[10]), 2);  // two entries
  EXPECT_NE(zip.find("shadows/pcf.glsl// mine\n"), std::string::npos) << "stored: the name, then the bytes as they are";
}
