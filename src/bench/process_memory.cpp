#include "bench/process_memory.h"

#include <cstdio>
#include <fstream>

namespace reflect {

ProcessMemory processMemory() {
  ProcessMemory memory;
  std::ifstream status("/proc/self/status");
  std::string line;
  bool peak = false, resident = false;
  while (std::getline(status, line)) {
    double kb = 0.0;
    if (std::sscanf(line.c_str(), "VmHWM: %lf kB", &kb) == 1) {
      memory.peakMb = kb / 1024.0;
      peak = true;
    } else if (std::sscanf(line.c_str(), "VmRSS: %lf kB", &kb) == 1) {
      memory.residentMb = kb / 1024.0;
      resident = true;
    }
  }
  memory.known = peak && resident;
  return memory;
}

std::string describe(const ProcessMemory& memory) {
  if (!memory.known) return "unknown (no /proc/self/status)";
  char text[96];
  std::snprintf(text, sizeof text, "peak (VmHWM) %.1f MB, resident (VmRSS) %.1f MB", memory.peakMb,
                memory.residentMb);
  return text;
}

}  // namespace reflect
