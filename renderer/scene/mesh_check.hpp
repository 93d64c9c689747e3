// The invariants every facet::Mesh must satisfy before it is built into a BVH or traced.
#pragma once

#include "scene/scene.hpp"

namespace facet {

// Throws facet::Error("mesh <name>: ...") unless: indices come in triples and address existing
// vertices; normals, uvs and tangents are empty or one per vertex (tangents only with normals);
// every position is finite and representable as a float (the GPU and Embree trace in float).
void check_mesh(const Mesh& mesh);

}  // namespace facet
