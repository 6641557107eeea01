// Temperature at an integration point, as ccx 2.20 evaluates it for the thermal strain
// (established with unit nodal temperatures on one-element decks):
//  * C3D8, C3D8I, C3D8R: the arithmetic mean of the 8 nodal values, uniform over the element;
//  * C3D20: trilinear interpolation of corner values, each corner value being the mean over
//    its 3 edges of the linear extrapolation 2*T_midside - T_far_corner;
//  * all others: the element's own shape functions.
#include "element/solid_kernels.hpp"

namespace kontakt::element {
namespace {

// (corner, midside, far corner) for the 24 corner-edge incidences of the 20-node brick.
constexpr int kHex20CornerEdges[8][3][2] = {
    {{8, 1}, {11, 3}, {16, 4}}, {{8, 0}, {9, 2}, {17, 5}},  {{9, 1}, {10, 3}, {18, 6}},
    {{10, 2}, {11, 0}, {19, 7}}, {{12, 5}, {15, 7}, {16, 0}}, {{12, 4}, {13, 6}, {17, 1}},
    {{13, 5}, {14, 7}, {18, 2}}, {{14, 6}, {15, 4}, {19, 3}}};

}  // namespace

Real point_temperature(ElementType type, const Vec3& xi, const ShapeVec& N, const VecX& dT) {
  if (dT.size() == 0) return 0;
  switch (type) {
    case ElementType::C3D8:
    case ElementType::C3D8I:
    case ElementType::C3D8R: return dT.mean();
    case ElementType::C3D20: {
      ShapeVec L;
      ShapeGrad dL;
      shape_functions(Topology::Hex8, xi, L, dL);
      Real t = 0;
      for (int c = 0; c < 8; ++c) {
        Real corner = 0;
        for (const auto& e : kHex20CornerEdges[c]) corner += 2 * dT(e[0]) - dT(e[1]);
        t += L(c) * corner / 3;
      }
      return t;
    }
    default: return N.dot(dT);
  }
}

}  // namespace kontakt::element
