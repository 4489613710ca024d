// Paths that must stay inside a folder: a shader's #include inside the shader folders, a glTF's
// buffers and images beside the glTF, a rubric's files inside a student's folder. Files handed
// in by other people name paths; these two checks keep those names from reaching anything else.
#pragma once
#include <filesystem>
#include <string_view>

namespace shadelab {

// `name` made lexically normal when it stays inside whatever folder it is joined to ("a/../b" ->
// "b"); empty for "", absolute names and names whose ".." climbs out ("../x", "a/../../x").
std::filesystem::path containedName(std::string_view name);

// Whether `file`'s real path lies inside `folder`'s real path, every symbolic link followed
// (in the file's name and in each folder above it). False when either does not exist.
bool realPathInside(const std::filesystem::path& folder, const std::filesystem::path& file);

}  // namespace shadelab
