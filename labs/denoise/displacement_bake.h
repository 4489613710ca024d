// Per-vertex offsets into a UV-space displacement map, and back.
//
// The homework: for each texel, find the vertex nearest to it in UV space (a nearest-neighbour
// search, FLANN) and store that vertex's offset along its normal, normalised to [0, 1] with a bias
// and a scale; the vertex shader reads the map at the vertex's UV and moves it. Two things go
// wrong along UV seams: copies of one position (same point, two UVs) read two texels that need not
// agree, and bilinear filtering mixes in texels of the neighbouring chart or of the empty gutter.
// The rasterising bake interpolates inside every UV triangle and dilates into the gutter, so a
// bilinear lookup near a chart's border still reads that chart's values.
//
// Maps are stored with row 0 at v = 0 (OpenGL's order); writing a PNG flips them. A map repeats
// when the mesh's UVs leave [0, 1] (Spot has a few just outside: its layout wraps), in the bake and
// in every lookup; otherwise it clamps, so a chart that touches the border (a sphere's seam at
// u = 1) reads its own edge, not a blend with the opposite one.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/lab/technique.h"
#include "app/util/job_runner.h"

namespace shadelab {

enum class BakeMethod {
  NearestExact,   // FLANN's single kd-tree: the true nearest vertex
  NearestApprox,  // FLANN's randomised kd-trees with a bounded number of checks
  Raster,         // barycentric interpolation inside each UV triangle, then gutter dilation
  Count
};
inline constexpr Named<BakeMethod> kBakeMethods[] = {{BakeMethod::NearestExact, "nearest-exact"},
                                                     {BakeMethod::NearestApprox, "nearest-approx"},
                                                     {BakeMethod::Raster, "raster"}};
static_assert(coversEnum<BakeMethod>(kBakeMethods));
enum class MapFormat { Unorm8, Unorm16, Float32, Count };
inline constexpr Named<MapFormat> kMapFormats[] = {
    {MapFormat::Unorm8, "8"}, {MapFormat::Unorm16, "16"}, {MapFormat::Float32, "float"}};
static_assert(coversEnum<MapFormat>(kMapFormats));

struct BakeSettings {
  BakeMethod method = BakeMethod::Raster;
  int resolution = 1024;  // square, 64..4096
  int checks = 32;        // NearestApprox: leaves visited per query (more: slower, more often right)
  int gutter = 4;         // Raster: texels of dilation around every chart
  MapFormat format = MapFormat::Unorm16;
  bool repeat = false;  // GL_REPEAT (UVs leave [0, 1]) or GL_CLAMP_TO_EDGE
  bool operator==(const BakeSettings&) const = default;
};

// Whether a mesh's UVs ask for a repeating map: any of them outside [0, 1].
bool uvsLeaveUnitSquare(std::span<const glm::vec2> uvs);

struct DisplacementMap {
  glm::ivec2 size{0};
  MapFormat format = MapFormat::Unorm16;
  std::vector<float> stored;        // what the texture holds: [0,1] (quantised) for unorm, offsets for float
  float bias = 0.0f, scale = 1.0f;  // offset = stored * scale + bias
  size_t covered = 0;               // texels inside some UV triangle (Raster), or all (Nearest)
  bool repeat = false;              // how it is sampled: GL_REPEAT or GL_CLAMP_TO_EDGE
  float decode(float s) const { return s * scale + bias; }
};

struct BakeResult {
  DisplacementMap map;
  double ms = 0;
  size_t wrongNeighbours = 0;  // NearestApprox: texels whose vertex differs from the exact one
  size_t overlapping = 0;      // Raster: texels inside two or more UV triangles (an overlapping layout)
  std::string error;
};

BakeResult bakeDisplacement(std::span<const glm::vec2> uvs, std::span<const uint32_t> indices,
                            std::span<const float> offsets, const BakeSettings& settings, JobContext* job = nullptr);

// Reads the map at `uv` as OpenGL does with the map's wrap mode: nearest texel, or bilinear between
// the four around it (texel centres at (i + 0.5) / size). Returns the decoded offset.
float sampleDisplacement(const DisplacementMap& map, glm::vec2 uv, bool bilinear);

// Encoded texels for upload or a PNG: one byte or one little-endian uint16 per texel (unorm), or
// the float itself. Rows bottom-up (v = 0 first) unless `topDown`.
std::vector<uint8_t> encodeMap(const DisplacementMap& map, bool topDown);

}  // namespace shadelab
