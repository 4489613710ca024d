// The shader preprocessor over a student's folder: the input is a set of files, each starting
// with a line "//@file NAME" (the first is the main file; without any marker the whole input is
// the main file). Includes, cycles, the sandbox and the #line numbering are all exercised, in the
// desktop dialect and in GLSL ES (interface blocks flattened).
#include <string>

#include "app/shader/preprocessor.h"
#include "app/util/contained_path.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  const fs::path root = shadelab::fuzz::scratchDir() / "student";
  std::error_code ec;
  fs::remove_all(root, ec);
  fs::create_directories(root / "shading");
  std::string_view rest = shadelab::fuzz::asText(data, size);
  std::string name = "shading/shade.frag";
  for (int files = 0; files < 16; ++files) {
    auto [text, tail] = shadelab::fuzz::splitAt(rest, "//@file ");
    const fs::path rel = shadelab::containedName(name);  // the scratch folder is the only place written
    if (!rel.empty() && rel.has_filename() && rel.filename() != ".") {
      const fs::path file = root / rel;
      fs::create_directories(file.parent_path(), ec);
      if (!ec && !fs::is_directory(file, ec))
        std::ofstream(file, std::ios::binary | std::ios::trunc).write(text.data(), std::streamsize(text.size()));
    }
    if (tail.data() == nullptr || tail.empty()) break;
    const size_t nl = tail.find('\n');
    name = std::string(tail.substr(0, std::min(nl, size_t(200))));
    rest = nl == std::string_view::npos ? std::string_view() : tail.substr(nl + 1);
  }
  const shadelab::ShaderSearchPath path({root});
  // Both dialects: the ES one also flattens interface blocks (the page's path).
  for (auto dialect : {shadelab::GlslDialect::Desktop, shadelab::GlslDialect::Es300}) {
    shadelab::setGlslDialect(dialect);
    const auto out = shadelab::preprocessShader(path, "shading/shade.frag", {{"SHADOWS", "1"}, {"PCF_SIZE", "3"}});
    (void)out;
  }
  shadelab::setGlslDialect(shadelab::GlslDialect::Desktop);
  return 0;
}
