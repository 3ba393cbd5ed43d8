#include "app/held_trees.h"

namespace reflect {

MeshTreeLookup heldTrees(const Demo& demo) {
  return [&demo](const std::string& name) -> std::shared_ptr<const MeshBvh> {
    const MeshBvh* tree = demo.meshBvh(name);
    if (tree == nullptr) return nullptr;
    return std::shared_ptr<const MeshBvh>(std::shared_ptr<const MeshBvh>(), tree);  // not owned
  };
}

}  // namespace reflect
