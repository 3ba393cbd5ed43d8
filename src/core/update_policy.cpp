// The update policies: their names, how far each lets a face lag, and which of a probe's stale
// faces each redraws this frame.
#include <algorithm>

#include "core/enum_names.h"
#include "core/frame_planner.h"
#include "core/planner_parts.h"

namespace reflect {

using planner::contains;

namespace {

constexpr EnumName<UpdatePolicy> kPolicyNames[] = {{UpdatePolicy::EveryFrame, "every-frame"},
                                                   {UpdatePolicy::WhenChanged, "when-changed"},
                                                   {UpdatePolicy::TimeSliced, "time-sliced"},
                                                   {UpdatePolicy::EveryNFrames, "every-n"}};

}  // namespace

const char* policyName(UpdatePolicy policy) {
  return nameIn(kPolicyNames, policy);
}

bool parsePolicy(const std::string& text, UpdatePolicy* policy) {
  return parseIn(kPolicyNames, text, policy);
}

int PlannerSettings::maxStalenessFrames() const {
  switch (policy) {
    case UpdatePolicy::TimeSliced: {
      const int k = std::clamp(facesPerFrame, 1, 6);
      return (6 + k - 1) / k - 1;
    }
    case UpdatePolicy::EveryNFrames:
      return std::max(everyN, 1) - 1;
    default:
      return 0;
  }
}

std::vector<int> FramePlanner::chooseFaces(const std::vector<int>& stale,
                                           const PlannerSettings& settings,
                                           ProbeMemory& memory) const {
  switch (settings.policy) {
    case UpdatePolicy::EveryFrame:
    case UpdatePolicy::WhenChanged:
      return stale;
    case UpdatePolicy::EveryNFrames:
      if (frameIndex_ % static_cast<uint64_t>(std::max(settings.everyN, 1)) == 0) return stale;
      return {};
    case UpdatePolicy::TimeSliced: {
      // Round robin from a cursor, so every stale face is reached within ceil(6/k) frames.
      const int k = std::clamp(settings.facesPerFrame, 1, 6);
      std::vector<int> chosen;
      for (int step = 0; step < 6 && static_cast<int>(chosen.size()) < k; ++step) {
        const int face = (memory.sliceCursor + step) % 6;
        if (contains(stale, face)) chosen.push_back(face);
      }
      if (!chosen.empty()) memory.sliceCursor = (chosen.back() + 1) % 6;
      std::sort(chosen.begin(), chosen.end());
      return chosen;
    }
  }
  return stale;
}

}  // namespace reflect
