// A GL ES 3.0 context with no display and no window (Mesa's surfaceless platform), for the CLI
// and the GL tests. Rendering goes into framebuffers the caller creates.
#pragma once

#include <memory>
#include <string>

#include "core/result.h"

namespace reflect {

class HeadlessGlContext {
 public:
  static Result<std::unique_ptr<HeadlessGlContext>> create();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  // "OpenGL ES 3.2 Mesa ... | llvmpipe ..."
  std::string description() const;

 private:
  HeadlessGlContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace reflect
