#include "element/element_type.hpp"

#include <array>
#include <cctype>
#include <vector>

#include "core/error.hpp"

namespace kontakt::element {
namespace {

constexpr std::array<ElementTraits, 9> kTraits = {{
    {ElementType::C3D4, "C3D4", 4, 4, 1, 4, false},
    {ElementType::C3D6, "C3D6", 6, 6, 2, 5, false},
    {ElementType::C3D8, "C3D8", 8, 8, 8, 6, false},
    {ElementType::C3D8R, "C3D8R", 8, 8, 1, 6, false},
    {ElementType::C3D8I, "C3D8I", 8, 8, 8, 6, false},
    {ElementType::C3D10, "C3D10", 10, 4, 4, 4, true},
    {ElementType::C3D15, "C3D15", 15, 6, 9, 5, true},
    {ElementType::C3D20, "C3D20", 20, 8, 27, 6, true},
    {ElementType::C3D20R, "C3D20R", 20, 8, 8, 6, true},
}};

// Corner nodes of each face (0-based), ordered so the right-hand normal points outward.
// ccx lists hex/tet faces and wedge triangles with the inward normal (hex S1 = 1-2-3-4):
// those are reversed here; the wedge quadrilaterals (S3 = 1-2-5-4) already point outward.
using Faces = std::vector<std::vector<int>>;
const Faces kHexFaces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
const Faces kTetFaces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
const Faces kWedgeFaces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};

// Midside node (0-based) on each corner pair of the quadratic types.
using Edges = std::vector<std::array<int, 3>>;
const Edges kHex20Edges = {{0, 1, 8},  {1, 2, 9},  {2, 3, 10}, {3, 0, 11}, {4, 5, 12}, {5, 6, 13},
                           {6, 7, 14}, {7, 4, 15}, {0, 4, 16}, {1, 5, 17}, {2, 6, 18}, {3, 7, 19}};
const Edges kTet10Edges = {{0, 1, 4}, {1, 2, 5}, {2, 0, 6}, {0, 3, 7}, {1, 3, 8}, {2, 3, 9}};
const Edges kWedge15Edges = {{0, 1, 6},  {1, 2, 7},  {2, 0, 8},  {3, 4, 9}, {4, 5, 10},
                             {5, 3, 11}, {0, 3, 12}, {1, 4, 13}, {2, 5, 14}};

int midside(const Edges& edges, int a, int b) {
  for (const auto& e : edges)
    if ((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) return e[2];
  throw SolverError("element face table: missing edge");
}

// Corners followed by the midside node of each consecutive corner pair.
Faces with_midsides(const Faces& corners, const Edges& edges) {
  Faces out;
  for (const auto& f : corners) {
    std::vector<int> g = f;
    for (std::size_t i = 0; i < f.size(); ++i) g.push_back(midside(edges, f[i], f[(i + 1) % f.size()]));
    out.push_back(g);
  }
  return out;
}

const Faces& faces_of(ElementType type) {
  static const Faces hex20 = with_midsides(kHexFaces, kHex20Edges);
  static const Faces tet10 = with_midsides(kTetFaces, kTet10Edges);
  static const Faces wedge15 = with_midsides(kWedgeFaces, kWedge15Edges);
  switch (type) {
    case ElementType::C3D4: return kTetFaces;
    case ElementType::C3D10: return tet10;
    case ElementType::C3D6: return kWedgeFaces;
    case ElementType::C3D15: return wedge15;
    case ElementType::C3D8:
    case ElementType::C3D8R:
    case ElementType::C3D8I: return kHexFaces;
    case ElementType::C3D20:
    case ElementType::C3D20R: return hex20;
  }
  throw SolverError("face_nodes: unknown element type");
}

}  // namespace

const ElementTraits& traits(ElementType type) {
  for (const auto& t : kTraits)
    if (t.type == type) return t;
  throw SolverError("traits: unknown element type");
}

std::optional<ElementType> element_type_from_name(std::string_view name) {
  for (const auto& t : kTraits) {
    if (t.name.size() != name.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < name.size() && same; ++i)
      same = std::toupper(static_cast<unsigned char>(name[i])) == t.name[i];
    if (same) return t.type;
  }
  return std::nullopt;
}

std::span<const int> face_nodes(ElementType type, int face) {
  const Faces& faces = faces_of(type);
  KONTAKT_REQUIRE(face >= 1 && face <= static_cast<int>(faces.size()),
                  "face_nodes: face number out of range");
  return faces[face - 1];
}

}  // namespace kontakt::element
