// Whether a mesh is the closed, outward-wound surface of a solid. Its back faces then never show
// from a point outside it: the main pass can skip them (half the fragments a sphere sends to the
// mirror's shader, each a traced ray) and draw the same pixels.
#pragma once

#include "core/mesh_data.h"

namespace reflect {

// True when, with vertices at the same position taken as one, every edge of a triangle is met
// once in each direction (once by this triangle, once reversed by its neighbour) and the
// enclosed volume is positive (counter-clockwise seen from outside). Triangles whose corners
// repeat a position cover nothing and are left out. False for an empty mesh, an open surface (a
// ground quad, a figure with a hole), a flipped triangle or an inside-out solid.
bool isClosedOutward(const MeshData& mesh);

}  // namespace reflect
