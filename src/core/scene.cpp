#include "core/scene.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace reflect {

glm::mat4 Scene::modelMatrix(const SceneObject& object, double orbitDegrees) const {
  if (!object.orbits) return object.placement;
  const glm::mat4 orbit = glm::rotate(glm::mat4(1.0f), glm::radians(static_cast<float>(orbitDegrees)),
                                      glm::vec3(0.0f, 1.0f, 0.0f));
  return orbit * object.placement;
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
    if (objects[i].reflective) return static_cast<int>(i);
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
  SceneObject ground{"quad.obj", translateScale({-1, -2, 4}, {100, 1, 100}), false,
                     {0.4f, 0.4f, 1.0f}};
  SceneObject sonic{"sonic.obj", translateScale({-2, -0.5f, 2}, glm::vec3(0.05f)), true,
                    {0.4f, 1.0f, 0.4f}};
  SceneObject mario{"mario.obj", translateScale({2.5f, -0.5f, 1.5f}, glm::vec3(0.02f)), true,
                    {1.0f, 0.4f, 0.4f}};
  SceneObject sphere{"sphere.obj", translateScale({0, 0, 0}, glm::vec3(0.5f)), false,
                     {0.95f, 0.85f, 0.4f}};
  sphere.reflective = true;
  scene.objects = {ground, sonic, mario, sphere};
  return scene;
}

}  // namespace reflect
