#include "gfx/gpu_timer.h"

#include <cstring>

namespace reflect {
namespace {

constexpr GLenum kTimeElapsed = 0x88BF;  // GL_TIME_ELAPSED_EXT
constexpr GLenum kGpuDisjoint = 0x8FBB;  // GL_GPU_DISJOINT_EXT

bool hasExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const char* ext =
        reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (ext && std::strcmp(ext, name) == 0) return true;
  }
  return false;
}

}  // namespace

GpuTimer::GpuTimer() {
  available_ = hasExtension("GL_EXT_disjoint_timer_query") ||
               hasExtension("GL_EXT_disjoint_timer_query_webgl2") ||
               hasExtension("EXT_disjoint_timer_query_webgl2");
  if (!available_) return;
  for (auto& slot : queries_) {
    for (QueryHandle& query : slot) query = QueryHandle(genQuery());
  }
  // Some drivers list the extension but refuse the target through the core entry points.
  glBeginQuery(kTimeElapsed, queries_[0][0].id());
  glEndQuery(kTimeElapsed);
  if (glGetError() != GL_NO_ERROR) {
    queries_ = {};
    available_ = false;
    return;
  }
  GLuint discard = 0;
  glGetQueryObjectuiv(queries_[0][0].id(), GL_QUERY_RESULT, &discard);
}

void GpuTimer::begin(Pass pass) {
  if (!available_) return;
  glBeginQuery(kTimeElapsed, queries_[static_cast<size_t>(slot_)][pass].id());
  pending_[static_cast<size_t>(slot_)][pass] = true;
}

void GpuTimer::end() {
  if (available_) glEndQuery(kTimeElapsed);
}

void GpuTimer::endFrame() {
  if (!available_) return;
  slot_ = (slot_ + 1) % kSlots;
  // The slot now up next is the oldest: read what finished, without waiting for what did not.
  GLint disjoint = 0;
  glGetIntegerv(kGpuDisjoint, &disjoint);
  for (int pass = 0; pass < 2; ++pass) {
    if (!pending_[static_cast<size_t>(slot_)][static_cast<size_t>(pass)]) continue;
    const GLuint query = queries_[static_cast<size_t>(slot_)][static_cast<size_t>(pass)].id();
    GLuint ready = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) continue;
    GLuint nanoseconds = 0;  // 32 bits: enough for passes under 4 s
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &nanoseconds);
    pending_[static_cast<size_t>(slot_)][static_cast<size_t>(pass)] = false;
    if (!disjoint) last_[static_cast<size_t>(pass)] = nanoseconds / 1e6;
  }
}

}  // namespace reflect
