// This process's memory as Linux reports it (/proc/self/status): what `reflect bench` prints after
// loading a scene. Printing only: the numbers wander with the driver's own heap.
#pragma once

#include <string>

namespace reflect {

struct ProcessMemory {
  bool known = false;
  double peakMb = 0.0;      // VmHWM: the largest resident set so far
  double residentMb = 0.0;  // VmRSS: the resident set now
};
ProcessMemory processMemory();
// "peak (VmHWM) 123.4 MB, resident (VmRSS) 120.1 MB", or "unknown (no /proc/self/status)".
std::string describe(const ProcessMemory& memory);

}  // namespace reflect
