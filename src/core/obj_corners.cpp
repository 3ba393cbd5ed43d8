#include "core/obj_corners.h"

#include <algorithm>
#include <cstdint>

#include "core/obj_tokens.h"

namespace reflect {
namespace {

// Field 0 of a corner (its position) must be defined already; returns the problem, or "".
std::string rangeProblem(size_t field, long index, long count) {
  static const char* const kKinds[3] = {"vertex", "texture coordinate", "normal"};
  // Index 0 is never valid.
  if (index == 0 || (field == 0 && (index > count || index < -count))) {
    return std::string(kKinds[field]) + " index " + std::to_string(index) + " is out of range (" +
           std::to_string(count) + " defined so far)";
  }
  return {};
}

// A corner's field (0: position, 1: texture coordinate, 2: normal), in range, into the corner.
void storeField(size_t field, long index, long count, ObjCorner* out, CornerReferences* refs) {
  if (field == 0) {
    out->position = static_cast<uint32_t>(index > 0 ? index - 1 : count + index);
    return;
  }
  const size_t k = field - 1;  // 0: texture coordinate, 1: normal
  refs->largest[k] = std::max(refs->largest[k], index);
  if (index < -count) refs->before[k] = true;
  if (field != 2) return;
  if (index < 0) {
    out->normal = index < -count ? -1 : static_cast<int32_t>(count + index);
  } else {
    // Past INT32_MAX no file can define it: it stays undefined.
    out->normal = static_cast<int32_t>(std::min<long>(index - 1, INT32_MAX));
    if (index > count) refs->forwardNormal = true;
  }
}

}  // namespace

std::string readObjCorner(std::string_view corner, const ObjCounts& defined, ObjCorner* out,
                          CornerReferences* refs) {
  const size_t available[3] = {defined.positions, defined.texcoords, defined.normals};
  size_t field = 0;
  size_t start = 0;
  while (start <= corner.size() && field < 3) {
    const size_t slash = corner.find('/', start);
    const std::string_view part = corner.substr(
        start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    // An empty field is only "v//n"'s texture coordinate: a trailing empty one ("1//", "1/2/")
    // would make tinyobjloader read the next corner's number as the index.
    if (!part.empty() || field == 0 || slash == std::string_view::npos) {
      long index = 0;
      if (!parseObjIndex(part, &index)) return "'" + std::string(corner) + "' is not a face index";
      const long count = static_cast<long>(available[field]);
      std::string problem = rangeProblem(field, index, count);
      if (!problem.empty()) return problem;
      storeField(field, index, count, out, refs);
    }
    if (slash == std::string_view::npos) return {};
    start = slash + 1;
    ++field;
  }
  return "'" + std::string(corner) + "' has too many '/' fields";
}

void UndefinedReferences::noteLine(size_t line, long largest, bool before, size_t defined) {
  if (before && firstBefore_ == 0) firstBefore_ = line;
  if (largest <= static_cast<long>(defined)) return;
  if (pendingStart_ < pending_.size() && largest <= pending_.back().second) return;
  pending_.emplace_back(line, largest);
}

void UndefinedReferences::defined(size_t count) {
  while (pendingStart_ < pending_.size() &&
         pending_[pendingStart_].second <= static_cast<long>(count)) {
    ++pendingStart_;
  }
  if (pendingStart_ == pending_.size()) {
    pending_.clear();
    pendingStart_ = 0;
  }
}

size_t UndefinedReferences::firstLine(size_t total) const {
  size_t after = 0;
  for (size_t i = pendingStart_; i < pending_.size(); ++i) {
    if (pending_[i].second > static_cast<long>(total)) {
      after = pending_[i].first;
      break;
    }
  }
  if (firstBefore_ == 0) return after;
  if (after == 0) return firstBefore_;
  return std::min(firstBefore_, after);
}

}  // namespace reflect
