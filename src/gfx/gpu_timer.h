// GPU time of the capture and main passes from timer queries (EXT_disjoint_timer_query natively,
// EXT_disjoint_timer_query_webgl2 in the browser). Results arrive a frame or two late, so the
// queries never stall the pipeline; without the extension the timer is off and the caller times
// on the CPU with a wait for the GPU instead.
#pragma once

#include <array>
#include <optional>

#include "gfx/gl_handle.h"

namespace reflect {

class GpuTimer {
 public:
  enum Pass { kCapture = 0, kMain = 1 };

  GpuTimer();  // queries the extension; available() says whether it is there

  bool available() const { return available_; }
  void begin(Pass pass);
  void end();
  // Called once a frame after both passes: collects finished results and moves to the next slot.
  void endFrame();
  // The most recent complete measurement of each pass, in ms (nullopt until one has arrived).
  std::optional<double> lastMs(Pass pass) const { return last_[pass]; }

 private:
  static constexpr int kSlots = 3;  // frames in flight before a result is read
  bool available_ = false;
  std::array<std::array<QueryHandle, 2>, kSlots> queries_;
  std::array<std::array<bool, 2>, kSlots> pending_{};
  int slot_ = 0;
  std::array<std::optional<double>, 2> last_{};
};

}  // namespace reflect
