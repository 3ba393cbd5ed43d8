// The limits a traced ray keeps to, one rule for both tracers: the Embree reference
// (src/reference) and the shader's (shaders/exact_trace.glsl, which gets them as #defines from
// gfx/program_key.cpp).
#pragma once

namespace reflect {

// A ray that has left this many mirror or glass surfaces shows the background instead of
// following the next one.
inline constexpr int kMaxBounces = 4;
// Inside glass, a ray past the critical angle reflects and goes on, this many times at most.
inline constexpr int kMaxInternalReflections = 8;

}  // namespace reflect
