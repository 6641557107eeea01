#include "element/quadrature.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace kontakt::element {
namespace {

using Rule = std::vector<QuadraturePoint>;

void gauss_1d(int n, std::vector<Real>& x, std::vector<Real>& w) {
  if (n == 1) { x = {0.0}; w = {2.0}; }
  if (n == 2) { const Real a = 1 / std::sqrt(3.0); x = {-a, a}; w = {1.0, 1.0}; }
  if (n == 3) {
    const Real a = std::sqrt(0.6);
    x = {-a, 0.0, a};
    w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  }
}

// Tensor-product brick rule: xi fastest, then eta, then zeta.
Rule gauss_hex(int n) {
  std::vector<Real> x, w;
  gauss_1d(n, x, w);
  Rule r;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) r.push_back({Vec3(x[i], x[j], x[k]), w[i] * w[j] * w[k]});
  return r;
}

Rule gauss_quad(int n) {
  std::vector<Real> x, w;
  gauss_1d(n, x, w);
  Rule r;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) r.push_back({Vec3(x[i], x[j], 0), w[i] * w[j]});
  return r;
}

Rule tet4_rule() {
  const Real a = (5 - std::sqrt(5.0)) / 20, b = (5 + 3 * std::sqrt(5.0)) / 20;
  const Real w = 1.0 / 24;
  return {{Vec3(a, a, a), w}, {Vec3(b, a, a), w}, {Vec3(a, b, a), w}, {Vec3(a, a, b), w}};
}

// Triangle rule x Gauss in zeta; triangle points fastest.
Rule wedge_rule(const std::vector<std::array<Real, 3>>& tri, int nz) {
  std::vector<Real> z, wz;
  gauss_1d(nz, z, wz);
  Rule r;
  for (int k = 0; k < nz; ++k)
    for (const auto& p : tri) r.push_back({Vec3(p[0], p[1], z[k]), p[2] * wz[k]});
  return r;
}

// Dunavant degree-5, 7-point triangle rule (weights sum to 1/2).
Rule tri7_rule() {
  const Real s = std::sqrt(15.0);
  const Real a1 = (6 - s) / 21, b1 = (9 + 2 * s) / 21, w1 = (155 - s) / 2400;
  const Real a2 = (6 + s) / 21, b2 = (9 - 2 * s) / 21, w2 = (155 + s) / 2400;
  return {{Vec3(1.0 / 3, 1.0 / 3, 0), 9.0 / 80}, {Vec3(a1, a1, 0), w1}, {Vec3(b1, a1, 0), w1},
          {Vec3(a1, b1, 0), w1},                 {Vec3(a2, a2, 0), w2}, {Vec3(b2, a2, 0), w2},
          {Vec3(a2, b2, 0), w2}};
}

}  // namespace

std::span<const QuadraturePoint> volume_rule(ElementType type) {
  static const Rule hex1 = gauss_hex(1), hex2 = gauss_hex(2), hex3 = gauss_hex(3);
  static const Rule tet1 = {{Vec3(0.25, 0.25, 0.25), 1.0 / 6}};
  static const Rule tet4 = tet4_rule();
  static const Rule wedge2 = wedge_rule({{1.0 / 3, 1.0 / 3, 0.5}}, 2);
  static const Rule wedge9 =
      wedge_rule({{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}}, 3);
  switch (type) {
    case ElementType::C3D8R: return hex1;
    case ElementType::C3D8:
    case ElementType::C3D8I:
    case ElementType::C3D20R: return hex2;
    case ElementType::C3D20: return hex3;
    case ElementType::C3D4: return tet1;
    case ElementType::C3D10: return tet4;
    case ElementType::C3D6: return wedge2;
    case ElementType::C3D15: return wedge9;
  }
  throw SolverError("volume_rule: unknown element type");
}

std::span<const QuadraturePoint> face_rule(Topology face) {
  static const Rule tri7 = tri7_rule();
  static const Rule quad9 = gauss_quad(3);
  if (face == Topology::Tri3 || face == Topology::Tri6) return tri7;
  if (face == Topology::Quad4 || face == Topology::Quad8) return quad9;
  throw SolverError("face_rule: not a face topology");
}

Real reference_measure(Topology topo) {
  switch (topo) {
    case Topology::Hex8:
    case Topology::Hex20: return 8;
    case Topology::Tet4:
    case Topology::Tet10: return 1.0 / 6;
    case Topology::Wedge6:
    case Topology::Wedge15: return 1;
    case Topology::Tri3:
    case Topology::Tri6: return 0.5;
    case Topology::Quad4:
    case Topology::Quad8: return 4;
  }
  return 0;
}

}  // namespace kontakt::element
