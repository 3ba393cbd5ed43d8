#include "core/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace reflect {

glm::mat4 Scene::modelMatrix(const SceneObject& object, double seconds) const {
  if (object.motion == Motion::None || glm::length(object.axis) == 0.0f) return object.placement;
  // The angle is wrapped in double precision, so it does not drift after long runs.
  const double degrees = std::fmod(object.degreesPerSecond * seconds, 360.0);
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(static_cast<float>(degrees)),
                                     glm::normalize(object.axis));
  return object.motion == Motion::Orbit ? turn * object.placement : object.placement * turn;
}

std::vector<std::string> Scene::meshNames() const {
  std::vector<std::string> names;
  for (const SceneObject& o : objects) {
    if (std::find(names.begin(), names.end(), o.mesh) == names.end()) names.push_back(o.mesh);
  }
  return names;
}

int Scene::reflectorIndex() const {
  for (size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].needsLiveProbe()) return static_cast<int>(i);
  }
  return -1;
}

namespace {
glm::mat4 translateScale(glm::vec3 t, glm::vec3 s) {
  return glm::scale(glm::translate(glm::mat4(1.0f), t), s);
}
}  // namespace

Scene makeDynamicReflectionScene() {
  Scene scene;
  SceneObject ground;
  ground.mesh = "quad.obj";
  ground.placement = translateScale({-1, -2, 4}, {100, 1, 100});
  ground.colour = {0.4f, 0.4f, 1.0f};
  SceneObject sonic;
  sonic.mesh = "sonic.obj";
  sonic.placement = translateScale({-2, -0.5f, 2}, glm::vec3(0.05f));
  sonic.motion = Motion::Orbit;
  sonic.colour = {0.4f, 1.0f, 0.4f};
  SceneObject mario = sonic;
  mario.mesh = "mario.obj";
  mario.placement = translateScale({2.5f, -0.5f, 1.5f}, glm::vec3(0.02f));
  mario.colour = {1.0f, 0.4f, 0.4f};
  SceneObject sphere;
  sphere.mesh = "sphere.obj";
  sphere.placement = translateScale({0, 0, 0}, glm::vec3(0.5f));
  sphere.colour = {0.95f, 0.85f, 0.4f};
  sphere.material = Material::Mirror;
  scene.objects = {ground, sonic, mario, sphere};
  return scene;
}

}  // namespace reflect
