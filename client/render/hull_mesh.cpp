#include "client/render/hull_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace ocean::render {
namespace {

constexpr int kStations = 14;
constexpr glm::vec3 kTopsides{0.08f, 0.12f, 0.22f}, kBottom{0.45f, 0.09f, 0.07f};
constexpr glm::vec3 kDeck{0.55f, 0.50f, 0.42f}, kHouse{0.82f, 0.83f, 0.84f};

// A station's cross-section at u in [0, 1] from stern to stem: half-width at the deck and at the
// bilge, the deck's height, the keel's depth.
struct Section {
  float x, half_deck, half_bilge, deck_y, keel_y;
};

Section section(float u, float length, float beam, float draft, float freeboard) {
  // Full from a fifth to 55 % of the length, a slightly narrower transom, an elliptic bow.
  float w = 1.0f;
  if (u < 0.2f) w = 0.86f + 0.14f * u / 0.2f;
  if (u > 0.55f) w = std::sqrt(std::max(0.0f, 1.0f - std::pow((u - 0.55f) / 0.45f, 2.0f)));
  const float half = 0.5f * beam * w;
  const float sheer = 1.0f + 0.35f * std::max(0.0f, (u - 0.6f) / 0.4f);  // the bow rises
  const float keel = draft * (u > 0.8f ? std::max(0.3f, 1.0f - (u - 0.8f) / 0.2f * 0.7f) : 1.0f);
  return {(u - 0.5f) * length, half, 0.85f * half, freeboard * sheer, -keel};
}

class Builder {
 public:
  explicit Builder(HullMesh& mesh) : mesh_(mesh) {}
  // A flat polygon (convex, counter-clockwise seen from outside), one colour; degenerate ones skipped.
  void face(std::initializer_list<glm::vec3> corners, glm::vec3 colour) {
    const std::vector<glm::vec3> p(corners);
    glm::vec3 n{0.0f};
    for (std::size_t i = 1; i + 1 < p.size(); ++i) n += glm::cross(p[i] - p[0], p[i + 1] - p[0]);
    if (glm::length(n) < 1e-6f) return;
    n = glm::normalize(n);
    const auto first = static_cast<std::uint16_t>(mesh_.vertices.size());
    for (const glm::vec3& c : p) {
      mesh_.vertices.push_back({c, n, colour});
      mesh_.radius_m = std::max(mesh_.radius_m, glm::length(c));
    }
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
      mesh_.indices.insert(mesh_.indices.end(), {first, static_cast<std::uint16_t>(first + i), static_cast<std::uint16_t>(first + i + 1)});
  }
  // An axis-aligned box from lo to hi: its five visible faces.
  void box(glm::vec3 lo, glm::vec3 hi, glm::vec3 colour) {
    face({{lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}}, colour);
    face({{hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}}, colour);
    face({{lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}}, colour);
    face({{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}, colour);
    face({{lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z}}, colour);
  }

 private:
  HullMesh& mesh_;
};

// The side of one segment between two stations, split at the waterline by colour.
glm::vec3 side_colour(float mid_y) { return mid_y < 0.0f ? kBottom : kTopsides; }

}  // namespace

HullMesh hull_mesh(float length_m, float beam_m, float draft_m) {
  HullMesh mesh;
  mesh.freeboard_m = 0.6f * draft_m + 0.03f * length_m + 0.3f;
  Builder b(mesh);
  for (int i = 0; i < kStations; ++i) {
    const Section a = section(static_cast<float>(i) / kStations, length_m, beam_m, draft_m, mesh.freeboard_m);
    const Section c = section(static_cast<float>(i + 1) / kStations, length_m, beam_m, draft_m, mesh.freeboard_m);
    const float bilge_a = 0.45f * a.keel_y, bilge_c = 0.45f * c.keel_y;
    for (const float s : {-1.0f, 1.0f}) {  // port (-z), starboard (+z)
      const glm::vec3 deck_a{a.x, a.deck_y, s * a.half_deck}, deck_c{c.x, c.deck_y, s * c.half_deck};
      const glm::vec3 bilge_pa{a.x, bilge_a, s * a.half_bilge}, bilge_pc{c.x, bilge_c, s * c.half_bilge};
      const glm::vec3 keel_a{a.x, a.keel_y, 0.0f}, keel_c{c.x, c.keel_y, 0.0f};
      // Winding flips with the side so every face looks outwards.
      if (s > 0) {
        b.face({deck_a, bilge_pa, bilge_pc, deck_c}, side_colour(0.5f * (a.deck_y + bilge_a)));
        b.face({bilge_pa, keel_a, keel_c, bilge_pc}, kBottom);
        b.face({deck_a, deck_c, {c.x, c.deck_y, 0.0f}, {a.x, a.deck_y, 0.0f}}, kDeck);
      } else {
        b.face({deck_a, deck_c, bilge_pc, bilge_pa}, side_colour(0.5f * (a.deck_y + bilge_a)));
        b.face({bilge_pa, bilge_pc, keel_c, keel_a}, kBottom);
        b.face({deck_a, {a.x, a.deck_y, 0.0f}, {c.x, c.deck_y, 0.0f}, deck_c}, kDeck);
      }
    }
  }
  // The transom, in two halves about the keel line.
  const Section t = section(0.0f, length_m, beam_m, draft_m, mesh.freeboard_m);
  for (const float s : {-1.0f, 1.0f}) {
    const glm::vec3 deck{t.x, t.deck_y, s * t.half_deck}, bilge{t.x, 0.45f * t.keel_y, s * t.half_bilge};
    const glm::vec3 top{t.x, t.deck_y, 0.0f}, keel{t.x, t.keel_y, 0.0f};
    if (s > 0) b.face({top, keel, bilge, deck}, kTopsides);
    else b.face({top, deck, bilge, keel}, kTopsides);
  }
  // A deckhouse amidships-aft, as most working boats have.
  const float house_h = std::min(2.6f, 0.12f * length_m + 0.8f), deck_y = mesh.freeboard_m;
  b.box({-0.18f * length_m, deck_y - 0.05f, -0.3f * beam_m}, {0.08f * length_m, deck_y + house_h, 0.3f * beam_m}, kHouse);
  return mesh;
}

}  // namespace ocean::render
