// The level-0 trees a Demo already holds (the exact mode's), as core/pixel_trace.h's
// MeshTreeLookup, for the CPU's walks over the same trees the shader traces (pick a pixel, the
// growth bench's ray count). Shared without ownership: the caller keeps the Demo alive while it
// walks them.
#pragma once

#include "app/demo.h"
#include "core/pixel_trace.h"

namespace reflect {

// Null for a mesh the demo holds no tree of (the exact tracer then neither draws nor meets it).
MeshTreeLookup heldTrees(const Demo& demo);

}  // namespace reflect
