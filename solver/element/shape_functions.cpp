#include "element/shape_functions.hpp"

#include <array>

#include "core/error.hpp"

namespace kontakt::element {
namespace {

// Corner sign patterns of the brick and the edges (corner pairs) carrying midside nodes.
constexpr std::array<std::array<int, 3>, 8> kHexCorner = {{{-1, -1, -1}, {1, -1, -1},
                                                           {1, 1, -1},   {-1, 1, -1},
                                                           {-1, -1, 1},  {1, -1, 1},
                                                           {1, 1, 1},    {-1, 1, 1}}};
constexpr std::array<std::array<int, 2>, 12> kHexEdge = {
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
constexpr std::array<std::array<int, 2>, 6> kTetEdge = {{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
constexpr std::array<std::array<int, 2>, 3> kTriEdge = {{{0, 1}, {1, 2}, {2, 0}}};
constexpr std::array<std::array<int, 2>, 4> kQuadCorner = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};

Vec3 hex20_node(int i) {
  if (i < 8) return Vec3(kHexCorner[i][0], kHexCorner[i][1], kHexCorner[i][2]);
  const auto [a, b] = kHexEdge[i - 8];
  return 0.5 * (hex20_node(a) + hex20_node(b));
}

void hex8(const Vec3& x, ShapeVec& N, ShapeGrad& dN) {
  for (int i = 0; i < 8; ++i) {
    const Real s = kHexCorner[i][0], t = kHexCorner[i][1], u = kHexCorner[i][2];
    const Real a = 1 + s * x(0), b = 1 + t * x(1), c = 1 + u * x(2);
    N(i) = a * b * c / 8;
    dN.row(i) << s * b * c / 8, a * t * c / 8, a * b * u / 8;
  }
}

void hex20(const Vec3& x, ShapeVec& N, ShapeGrad& dN) {
  for (int i = 0; i < 20; ++i) {
    const Vec3 p = hex20_node(i);
    const Real a = 1 + p(0) * x(0), b = 1 + p(1) * x(1), c = 1 + p(2) * x(2);
    if (i < 8) {
      const Real g = p(0) * x(0) + p(1) * x(1) + p(2) * x(2) - 2;
      N(i) = a * b * c * g / 8;
      dN.row(i) << p(0) * b * c * (g + a) / 8, p(1) * a * c * (g + b) / 8,
          p(2) * a * b * (g + c) / 8;
      continue;
    }
    // Midside: one natural coordinate of the node is zero; its factor is (1 - x^2).
    const int z = p(0) == 0 ? 0 : (p(1) == 0 ? 1 : 2);
    Vec3 f(a, b, c), df(p(0), p(1), p(2));
    f(z) = 1 - x(z) * x(z);
    df(z) = -2 * x(z);
    N(i) = f.prod() / 4;
    dN.row(i) << df(0) * f(1) * f(2) / 4, f(0) * df(1) * f(2) / 4, f(0) * f(1) * df(2) / 4;
  }
}

// Barycentric simplex interpolation (tri/tet), linear or quadratic.
template <int Dim>
void simplex(const Vec3& x, bool quadratic, ShapeVec& N, ShapeGrad& dN) {
  constexpr int nc = Dim + 1;
  Eigen::Matrix<Real, nc, 1> L;
  Eigen::Matrix<Real, nc, 3> dL = Eigen::Matrix<Real, nc, 3>::Zero();
  L(0) = 1;
  for (int d = 0; d < Dim; ++d) {
    L(0) -= x(d);
    L(d + 1) = x(d);
    dL(0, d) = -1;
    dL(d + 1, d) = 1;
  }
  if (!quadratic) {
    N.head<nc>() = L;
    dN.topRows<nc>() = dL;
    return;
  }
  for (int i = 0; i < nc; ++i) {
    N(i) = L(i) * (2 * L(i) - 1);
    dN.row(i) = (4 * L(i) - 1) * dL.row(i);
  }
  const int ne = Dim == 3 ? 6 : 3;
  for (int e = 0; e < ne; ++e) {
    const auto [a, b] = Dim == 3 ? kTetEdge[e] : kTriEdge[e];
    N(nc + e) = 4 * L(a) * L(b);
    dN.row(nc + e) = 4 * (L(a) * dL.row(b) + L(b) * dL.row(a));
  }
}

void wedge6(const Vec3& x, ShapeVec& N, ShapeGrad& dN) {
  const Real L[3] = {1 - x(0) - x(1), x(0), x(1)};
  const Real dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int k = 0; k < 2; ++k) {
    const Real s = k == 0 ? -1 : 1, h = 0.5 * (1 + s * x(2));
    for (int i = 0; i < 3; ++i) {
      N(3 * k + i) = L[i] * h;
      dN.row(3 * k + i) << dL[i][0] * h, dL[i][1] * h, 0.5 * s * L[i];
    }
  }
}

void wedge15(const Vec3& x, ShapeVec& N, ShapeGrad& dN) {
  const Real L[3] = {1 - x(0) - x(1), x(0), x(1)};
  const Real dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  const Real z = x(2), q = 1 - z * z;
  for (int k = 0; k < 2; ++k) {
    const Real s = k == 0 ? -1 : 1, h = 1 + s * z;
    for (int i = 0; i < 3; ++i) {  // corners: L h (2L - 1) / 2 - L q / 2
      const Real g = 0.5 * h * (2 * L[i] - 1) - 0.5 * q, dg = h;
      N(3 * k + i) = L[i] * g;
      const Real dgdz = 0.5 * s * (2 * L[i] - 1) + z;
      dN.row(3 * k + i) << dL[i][0] * (g + L[i] * dg), dL[i][1] * (g + L[i] * dg), L[i] * dgdz;
    }
    for (int e = 0; e < 3; ++e) {  // in-plane midsides: 2 La Lb h
      const auto [a, b] = kTriEdge[e];
      const int n = 6 + 3 * k + e;
      N(n) = 2 * L[a] * L[b] * h;
      dN.row(n) << 2 * h * (dL[a][0] * L[b] + L[a] * dL[b][0]),
          2 * h * (dL[a][1] * L[b] + L[a] * dL[b][1]), 2 * s * L[a] * L[b];
    }
  }
  for (int i = 0; i < 3; ++i) {  // vertical midsides: L q
    N(12 + i) = L[i] * q;
    dN.row(12 + i) << dL[i][0] * q, dL[i][1] * q, -2 * z * L[i];
  }
}

void quad(const Vec3& x, bool quadratic, ShapeVec& N, ShapeGrad& dN) {
  for (int i = 0; i < 4; ++i) {
    const Real s = kQuadCorner[i][0], t = kQuadCorner[i][1];
    const Real a = 1 + s * x(0), b = 1 + t * x(1);
    if (!quadratic) {
      N(i) = a * b / 4;
      dN.row(i) << s * b / 4, a * t / 4, 0;
      continue;
    }
    const Real g = s * x(0) + t * x(1) - 1;
    N(i) = a * b * g / 4;
    dN.row(i) << s * b * (g + a) / 4, t * a * (g + b) / 4, 0;
  }
  if (!quadratic) return;
  for (int e = 0; e < 4; ++e) {  // midsides of edges 1-2, 2-3, 3-4, 4-1
    const int a = e, b = (e + 1) % 4;
    const Real ps = 0.5 * (kQuadCorner[a][0] + kQuadCorner[b][0]);
    const Real pt = 0.5 * (kQuadCorner[a][1] + kQuadCorner[b][1]);
    if (ps == 0) {
      N(4 + e) = (1 - x(0) * x(0)) * (1 + pt * x(1)) / 2;
      dN.row(4 + e) << -x(0) * (1 + pt * x(1)), (1 - x(0) * x(0)) * pt / 2, 0;
    } else {
      N(4 + e) = (1 - x(1) * x(1)) * (1 + ps * x(0)) / 2;
      dN.row(4 + e) << (1 - x(1) * x(1)) * ps / 2, -x(1) * (1 + ps * x(0)), 0;
    }
  }
}

}  // namespace

int node_count(Topology topo) {
  static constexpr int kCount[] = {8, 20, 4, 10, 6, 15, 3, 6, 4, 8};
  return kCount[static_cast<int>(topo)];
}

int dimension(Topology topo) { return static_cast<int>(topo) >= static_cast<int>(Topology::Tri3) ? 2 : 3; }

Vec3 reference_node(Topology topo, int i) {
  ShapeVec N;
  ShapeGrad dN;
  switch (topo) {
    case Topology::Hex8:
    case Topology::Hex20: return hex20_node(i);
    case Topology::Quad4:
    case Topology::Quad8: {
      const Vec3 p = hex20_node(i < 4 ? i : i + 4);  // quad nodes = bottom hex face
      return Vec3(p(0), p(1), 0);
    }
    case Topology::Tet4:
    case Topology::Tet10:
    case Topology::Tri3:
    case Topology::Tri6: {
      const int nc = topo == Topology::Tet4 || topo == Topology::Tet10 ? 4 : 3;
      auto corner = [](int c) { Vec3 v = Vec3::Zero(); if (c > 0) v(c - 1) = 1; return v; };
      if (i < nc) return corner(i);
      const auto [a, b] = nc == 4 ? kTetEdge[i - nc] : kTriEdge[i - nc];
      return 0.5 * (corner(a) + corner(b));
    }
    case Topology::Wedge6:
    case Topology::Wedge15: {
      static constexpr Real kW[15][3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1},
                                         {1, 0, 1},  {0, 1, 1},  {.5, 0, -1}, {.5, .5, -1},
                                         {0, .5, -1}, {.5, 0, 1}, {.5, .5, 1}, {0, .5, 1},
                                         {0, 0, 0},  {1, 0, 0},  {0, 1, 0}};
      return Vec3(kW[i][0], kW[i][1], kW[i][2]);
    }
  }
  throw SolverError("reference_node: unknown topology");
}

void shape_functions(Topology topo, const Vec3& xi, ShapeVec& N, ShapeGrad& dN) {
  const int n = node_count(topo);
  N.resize(n);
  dN.setZero(n, 3);
  switch (topo) {
    case Topology::Hex8: hex8(xi, N, dN); return;
    case Topology::Hex20: hex20(xi, N, dN); return;
    case Topology::Tet4: simplex<3>(xi, false, N, dN); return;
    case Topology::Tet10: simplex<3>(xi, true, N, dN); return;
    case Topology::Wedge6: wedge6(xi, N, dN); return;
    case Topology::Wedge15: wedge15(xi, N, dN); return;
    case Topology::Tri3: simplex<2>(xi, false, N, dN); return;
    case Topology::Tri6: simplex<2>(xi, true, N, dN); return;
    case Topology::Quad4: quad(xi, false, N, dN); return;
    case Topology::Quad8: quad(xi, true, N, dN); return;
  }
}

Topology volume_topology(ElementType type) {
  switch (type) {
    case ElementType::C3D4: return Topology::Tet4;
    case ElementType::C3D10: return Topology::Tet10;
    case ElementType::C3D6: return Topology::Wedge6;
    case ElementType::C3D15: return Topology::Wedge15;
    case ElementType::C3D8:
    case ElementType::C3D8R:
    case ElementType::C3D8I: return Topology::Hex8;
    case ElementType::C3D20:
    case ElementType::C3D20R: return Topology::Hex20;
  }
  throw SolverError("volume_topology: unknown element type");
}

Topology face_topology(ElementType type, int face) {
  const bool quadratic = traits(type).is_quadratic;
  const Topology v = volume_topology(type);
  const bool tri = v == Topology::Tet4 || v == Topology::Tet10 ||
                   ((v == Topology::Wedge6 || v == Topology::Wedge15) && face <= 2);
  if (tri) return quadratic ? Topology::Tri6 : Topology::Tri3;
  return quadratic ? Topology::Quad8 : Topology::Quad4;
}

}  // namespace kontakt::element
