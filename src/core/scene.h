// What is in the scene, as data: meshes by name, transforms, colours, which object reflects,
// light, camera and capture settings. The renderer draws whatever this describes.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/camera.h"

namespace reflect {

struct PhongLight {
  glm::vec3 position{5.0f, 1.0f, 7.0f};
  float ambient = 0.2f;   // Ka
  float diffuse = 0.7f;   // Kd
  float specular = 1.0f;  // Ks
  float shininess = 10.0f;
};

struct SceneObject {
  std::string mesh;  // model file name, e.g. "mario.obj"
  // M = Ry(orbit angle) * placement when `orbits`, else placement.
  glm::mat4 placement{1.0f};
  bool orbits = false;
  glm::vec3 colour{1.0f};
  bool reflective = false;
  // Reflective shading: reflectionWeight * env + baseWeight * colour (the course: 0.78 and 0.3).
  float reflectionWeight = 0.78f;
  float baseWeight = 0.3f;
  // Reflectors with the same group >= 0 share one probe (see PlannedObject::probeGroup).
  int probeGroup = -1;
};

struct CaptureSettings {
  int faceSize = 256;
  float near = 1.0f;
  float far = 100.0f;
};

struct Scene {
  std::vector<SceneObject> objects;
  PhongLight light;
  CameraSettings camera;
  CaptureSettings capture;
  glm::vec3 clearColour{0.4f, 0.4f, 0.4f};

  glm::mat4 modelMatrix(const SceneObject& object, double orbitDegrees) const;
  // The distinct mesh names the scene uses, in first-use order.
  std::vector<std::string> meshNames() const;
  // Index of the reflective object, or -1 when the scene has none.
  int reflectorIndex() const;
};

// The course's Ex12-2 ("dynamic reflection"), with the values of SEED.md.
Scene makeDynamicReflectionScene();

}  // namespace reflect
