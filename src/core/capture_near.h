// Whether a scene's capture near plane lies inside its reflectors. A probe leaves out whatever is
// nearer its centre than the near plane; inside a mirror or glass object with a probe of its own,
// that is nothing the object could see. Outside it, a neighbour's near side or a figure passing
// close is cut out of the captures (docs/scenes.md): rough-spheres and frosted-glass had a near
// plane of 1 around spheres of radius 0.9 and 0.6.
#pragma once

#include <functional>
#include <string>

#include "core/mesh_data.h"
#include "core/scene.h"

namespace reflect {

// A mesh's bounds by name, or nullptr for one not loaded.
using MeshBoundsLookup = std::function<const Bounds*(const std::string&)>;

// "" when the near plane lies inside every object with a probe of its own at its centre (a mirror
// or glass object's, or a probe-lit figure's "own-probe"): its world box's smallest half side, at
// t = 0, is at least the near plane. Otherwise a message naming the scene, the objects and the
// largest near plane that would do.
std::string captureNearNotice(const Scene& scene, const MeshBoundsLookup& boundsOf);

}  // namespace reflect
