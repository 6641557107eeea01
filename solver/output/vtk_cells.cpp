#include "output/vtk_cells.hpp"

#include <array>

namespace kontakt::output {

namespace {
using element::ElementType;

// Tetrahedra and hexahedra: ccx/Abaqus order equals VTK order (corners with the first face
// counter-clockwise seen from the opposite corner/face; midsides on edges 0-1,1-2,2-0,0-3,1-3,
// 2-3 for the tet; 0-1,1-2,2-3,3-0,4-5,5-6,6-7,7-4,0-4,1-5,2-6,3-7 for the hex).
constexpr std::array<int, 4> kTet4{0, 1, 2, 3};
constexpr std::array<int, 10> kTet10{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
constexpr std::array<int, 8> kHex8{0, 1, 2, 3, 4, 5, 6, 7};
constexpr std::array<int, 20> kHex20{0,  1,  2,  3,  4,  5,  6,  7,  8,  9,
                                     10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
// Wedges: in ccx the right-hand normal of triangle 1-2-3 points toward triangle 4-5-6; in VTK
// the normal of (0,1,2) points away from (3,4,5). Swap the 2nd and 3rd node of each triangle;
// the midside nodes follow their edges: VTK edges (0,1),(1,2),(2,0) = ccx (1,3),(3,2),(2,1)
// -> ccx midsides 9,8,7; top likewise 12,11,10; vertical edges (0,3),(1,4),(2,5) = ccx
// (1,4),(3,6),(2,5) -> 13,15,14 (1-based ccx numbers).
constexpr std::array<int, 6> kWedge6{0, 2, 1, 3, 5, 4};
constexpr std::array<int, 15> kWedge15{0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13};

const VtkCell kCells[] = {
    {ElementType::C3D4, "C3D4", 4, 10, 6, kTet4},
    {ElementType::C3D6, "C3D6", 6, 13, 8, kWedge6},
    {ElementType::C3D8, "C3D8", 8, 12, 9, kHex8},
    {ElementType::C3D8R, "C3D8R", 8, 12, 9, kHex8},
    {ElementType::C3D8I, "C3D8I", 8, 12, 9, kHex8},
    {ElementType::C3D10, "C3D10", 10, 24, 38, kTet10},
    {ElementType::C3D15, "C3D15", 15, 26, 40, kWedge15},
    {ElementType::C3D20, "C3D20", 20, 25, 48, kHex20},
    {ElementType::C3D20R, "C3D20R", 20, 25, 48, kHex20},
};
}  // namespace

const VtkCell& vtk_cell(element::ElementType type) {
  for (const auto& c : kCells)
    if (c.type == type) return c;
  return kCells[0];  // unreachable: every enumerator is listed
}

}  // namespace kontakt::output
