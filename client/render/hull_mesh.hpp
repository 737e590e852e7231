// HullMesh: a vessel's hull from its length, beam and draft - the project's own simple geometry:
// a transom stern, full sides amidships, a bow that narrows to a stem and rises a little, a
// V bottom to a keel at the draft, a deck and a deckhouse - flat-shaded faces, coloured by what
// they are (topsides, antifouling below the waterline, deck, house). Pure (no GL): hull-local
// metres, +x towards the bow, +y up, +z to starboard, the waterline at y = 0.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::render {

struct HullVertex {
  glm::vec3 position;
  glm::vec3 normal;  // unit, outward (flat: one per face)
  glm::vec3 colour;  // linear RGB, before light
};

struct HullMesh {
  std::vector<HullVertex> vertices;
  std::vector<std::uint16_t> indices;  // triangles
  float freeboard_m = 0.0f;            // the deck's height above the waterline amidships
  float radius_m = 0.0f;               // of a sphere about the origin holding every vertex
};

HullMesh hull_mesh(float length_m, float beam_m, float draft_m);

}  // namespace ocean::render
