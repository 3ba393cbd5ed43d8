#include "core/accuracy_settings.h"

namespace reflect {

std::string AccuracySettings::describe() const {
  std::string s = captureAtOrigin ? "origin" : "centre";
  s += distanceIterations > 0 ? ", distance x" + std::to_string(distanceIterations) : ", plain";
  s += ", depth " + std::to_string(depthBits);
  s += mipmaps ? ", mipmapped" : ", linear";
  s += usesHalfFloat() ? ", RGBA16F" : ", RGBA8";
  s += mediump ? ", mediump" : ", highp";
  return s;
}

}  // namespace reflect
