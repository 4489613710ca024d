#include "app/gl/pass_timer.h"

#include <cassert>
#include <chrono>
#include <cstdlib>
#include <cstring>

namespace gl {

static double nowMs() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

PassTimer::PassTimer() {
  // WebGL2 has no 64-bit query read, and hands out a query's result only after the page has given
  // the frame back: without glGetQueryObjectui64v, passes are timed by the clock.
  const bool queries = glGetQueryObjectui64v != nullptr;
  clock_ = softwareRenderer() || !queries ? Clock::Finish : Clock::GpuQuery;
  if (!queries && esContext()) clock_ = Clock::Readback;
  if (const char* env = std::getenv("SHADELAB_TIMER")) {
    if (std::strcmp(env, "query") == 0 && queries) clock_ = Clock::GpuQuery;
    if (std::strcmp(env, "finish") == 0) clock_ = Clock::Finish;
    if (std::strcmp(env, "readback") == 0) clock_ = Clock::Readback;
  }
}

const char* PassTimer::clockName() const {
  switch (clock_) {
    case Clock::GpuQuery:
      return "GL_TIME_ELAPSED queries";
    case Clock::Finish:
      return "wall time between glFinish calls";
    case Clock::Readback:
      return "wall time between one-pixel reads (WebGL's finish does not wait)";
  }
  return "?";
}

void PassTimer::sync() {
  if (clock_ == Clock::Finish) {
    glFinish();
    return;
  }
  GLint read = 0, pack = 0, texture = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
  if (!syncTarget_) {
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    syncTexture_ = TextureName::make();
    glBindTexture(GL_TEXTURE_2D, syncTexture_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    syncTarget_ = FramebufferName::make();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, syncTarget_.get());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, syncTexture_.get(), 0);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, syncTarget_.get());
  if (pack) glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  unsigned char pixel[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  if (pack) glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(pack));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
}

void PassTimer::beginFrame() {
  passes_.clear();
  inPass_ = false;
}

void PassTimer::begin(std::string name) {
  assert(!inPass_ && "GPU passes cannot nest");
  const size_t q = passes_.size();
  if (clock_ != Clock::GpuQuery) {
    sync();  // earlier work must not count against this pass
  } else {
    if (q == pool_.size()) pool_.push_back(Query::make());
    glBeginQuery(GL_TIME_ELAPSED, pool_[q].get());
  }
  passes_.push_back({{std::move(name), 0.0, 0.0}, nowMs()});
  inPass_ = true;
}

void PassTimer::end() {
  assert(inPass_);
  Open& p = passes_.back();
  p.timing.cpuMs = nowMs() - p.start;
  if (clock_ != Clock::GpuQuery) {
    sync();
    p.timing.gpuMs = nowMs() - p.start;
  } else {
    glEndQuery(GL_TIME_ELAPSED);
  }
  inPass_ = false;
}

const std::vector<PassTiming>& PassTimer::endFrame() {
  last_.clear();
  // One wait for the whole frame, then every result is there: cheaper than a blocking read per
  // query, which some drivers serve by sleeping and waking up once per query.
  if (clock_ == Clock::GpuQuery && !passes_.empty()) glFinish();
  for (size_t i = 0; i < passes_.size(); ++i) {
    if (clock_ == Clock::GpuQuery) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(pool_[i].get(), GL_QUERY_RESULT, &ns);
      passes_[i].timing.gpuMs = double(ns) * 1e-6;
    }
    last_.push_back(passes_[i].timing);
  }
  passes_.clear();
  return last_;
}

}  // namespace gl
