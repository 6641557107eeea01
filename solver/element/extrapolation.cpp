// Integration point -> node extrapolation: the polynomial through (a subset of) the points,
// evaluated at the nodes' natural coordinates.
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/shape_functions.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {
namespace {

using Basis = std::function<VecX(const Vec3&)>;

VecX trilinear(const Vec3& p) {
  VecX v(8);
  v << 1, p(0), p(1), p(2), p(0) * p(1), p(1) * p(2), p(2) * p(0), p(0) * p(1) * p(2);
  return v;
}
VecX linear(const Vec3& p) { return Eigen::Vector4d(1, p(0), p(1), p(2)); }
VecX tri_linear_x_zeta_linear(const Vec3& p) {
  VecX v(6);
  v << 1, p(0), p(1), p(2), p(0) * p(2), p(1) * p(2);
  return v;
}

/// The 20-node serendipity functions as a fitting basis: the fit over the 27 points of the
/// 3x3x3 rule then gives the nodal values directly (ccx extrapolates C3D20 this way).
VecX hex20_shape_functions(const Vec3& p) {
  ShapeVec N;
  ShapeGrad dN;
  shape_functions(Topology::Hex20, p, N, dN);
  return N;
}

// ccx 2.20's C3D6 table (measured from .frd nodal stresses): linear zeta-extrapolation from
// points at -/+sqrt(3/5) to the faces, c = (1 + sqrt(5/3)) / 2, applied with the point order
// alternating by node number (nodes 1,3,5 lean on point 1, nodes 2,4,6 on point 2).
MatX ccx_wedge6_table() {
  const Real c = 0.5 * (1 + std::sqrt(5.0 / 3.0));
  MatX E(6, 2);
  for (int a = 0; a < 6; ++a) E.row(a) = a % 2 == 0 ? Eigen::RowVector2d(c, 1 - c) : Eigen::RowVector2d(1 - c, c);
  return E;
}

// E(node, ip) for the polynomial space `basis` fitted (least squares; interpolation when square)
// through the points `subset`.
MatX fit_through(ElementType type, const std::vector<int>& subset, const Basis& basis) {
  const auto rule = volume_rule(type);
  const Topology topo = volume_topology(type);
  const Index m = static_cast<Index>(subset.size());
  const Index nb = basis(Vec3::Zero()).size();
  MatX V(m, nb);
  for (Index r = 0; r < m; ++r) V.row(r) = basis(rule[subset[r]].xi).transpose();
  const MatX Vinv = (V.transpose() * V).inverse() * V.transpose();  // nb x m
  MatX E = MatX::Zero(node_count(topo), static_cast<Index>(rule.size()));
  for (Index a = 0; a < E.rows(); ++a) {
    const VecX w = Vinv.transpose() * basis(reference_node(topo, static_cast<int>(a)));
    for (Index r = 0; r < m; ++r) E(a, subset[r]) = w(r);
  }
  return E;
}

std::vector<int> all_points(ElementType type) {
  std::vector<int> s(volume_rule(type).size());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<int>(i);
  return s;
}

MatX build(ElementType type) {
  switch (type) {
    case ElementType::C3D8:
    case ElementType::C3D8I:
    case ElementType::C3D20R: return fit_through(type, all_points(type), trilinear);
    case ElementType::C3D20:  // least squares of the element's own interpolation over all 27
      return fit_through(type, all_points(type), hex20_shape_functions);  // points, as ccx
    case ElementType::C3D8R: return MatX::Ones(8, 1);
    case ElementType::C3D4: return MatX::Ones(4, 1);
    case ElementType::C3D10: return fit_through(type, all_points(type), linear);
    case ElementType::C3D6: return ccx_wedge6_table();
    case ElementType::C3D15:  // least squares over the 9 points, as ccx (matched to 1e-5)
      return fit_through(type, all_points(type), tri_linear_x_zeta_linear);
  }
  throw SolverError("ip_to_node_extrapolation: unknown element type");
}

}  // namespace

const MatX& ip_to_node_extrapolation(ElementType type) {
  static const std::array<MatX, 9> tables = [] {
    std::array<MatX, 9> t;
    for (int i = 0; i < 9; ++i) t[i] = build(static_cast<ElementType>(i));
    return t;
  }();
  return tables[static_cast<int>(type)];
}

}  // namespace kontakt::element
