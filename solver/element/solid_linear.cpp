#include "element/solid_linear.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/error.hpp"
#include "element/element_type.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

Mat6 elasticity_matrix(const PointElastic& point) {
  if (point.stiffness) return *point.stiffness;
  const Real E = point.constants.young, nu = point.constants.poisson;
  const Real lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Mat6 D = Mat6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    D(i, i) += 2 * mu;
    D(i + 3, i + 3) = mu;
  }
  return D;
}

PointGeometry point_geometry(Topology topo, const MatX3& X, const Vec3& xi) {
  PointGeometry g;
  ShapeGrad dN;
  shape_functions(topo, xi, g.N, dN);
  KONTAKT_REQUIRE(X.rows() == g.N.size(), "element: wrong number of nodal coordinates");
  g.J = dN.transpose() * X;
  g.detJ = g.J.determinant();
  KONTAKT_REQUIRE(g.detJ > 0, "element: non-positive Jacobian (distorted or inverted element)");
  g.dNdx = dN * g.J.inverse().transpose();
  return g;
}

PointGeometry rule_point_geometry(ElementType type, const MatX3& X, const Vec3& xi) {
  PointGeometry g = point_geometry(volume_topology(type), X, xi);
  if (type == ElementType::C3D8R) {
    Real volume = 0;
    mean_gradients(X, g.dNdx, volume);
    g.detJ = volume / volume_rule(type)[0].weight;
  }
  return g;
}

void b_matrix(const ShapeGrad& dNdx, BMatrix& B) {
  const int n = static_cast<int>(dNdx.rows());
  B.setZero(6, 3 * n);
  for (int a = 0; a < n; ++a) {
    const Real dx = dNdx(a, 0), dy = dNdx(a, 1), dz = dNdx(a, 2);
    B(0, 3 * a) = dx;
    B(1, 3 * a + 1) = dy;
    B(2, 3 * a + 2) = dz;
    B(3, 3 * a) = dy;
    B(3, 3 * a + 1) = dx;
    B(4, 3 * a) = dz;
    B(4, 3 * a + 2) = dx;
    B(5, 3 * a + 1) = dz;
    B(5, 3 * a + 2) = dy;
  }
}

Vec6 tensor_strain(const Vec6& engineering) {
  Vec6 e = engineering;
  e.tail<3>() *= 0.5;
  return e;
}

Vec6 thermal_strain(const PointElastic& mat) {
  Vec6 e = Vec6::Zero();
  e.head<3>().setConstant(mat.thermal_strain);
  return e;
}

void linear_stiffness(ElementType type, const MatX3& X, const ThermoElastic& mat, const VecX& dT,
                      MatX& K) {
  if (type == ElementType::C3D8I) {
    incompatible_stiffness(X, mat, dT, K);
    return;
  }
  const Topology topo = volume_topology(type);
  const int ndof = 3 * node_count(topo);
  K.setZero(ndof, ndof);
  BMatrix B;
  Real hourglass_modulus = 0;  // C3D8R: its one point's
  for (const auto& q : volume_rule(type)) {
    const PointGeometry g = rule_point_geometry(type, X, q.xi);
    const PointElastic m = point_material(mat, type, q.xi, g.N, dT);
    b_matrix(g.dNdx, B);
    K.noalias() += (q.weight * g.detJ) * (B.transpose() * elasticity_matrix(m) * B);
    hourglass_modulus = m.constants.young;
  }
  if (type == ElementType::C3D8R) {
    MatX Khg;
    hourglass_stiffness(X, hourglass_modulus, Khg);
    K += Khg;
  }
}

void thermal_load(ElementType type, const MatX3& X, const ThermoElastic& mat, const VecX& dT,
                  VecX& f) {
  if (type == ElementType::C3D8I) {
    incompatible_thermal_load(X, mat, dT, f);
    return;
  }
  const Topology topo = volume_topology(type);
  KONTAKT_REQUIRE(dT.size() == node_count(topo), "thermal_load: wrong number of temperatures");
  f.setZero(3 * node_count(topo));
  BMatrix B;
  for (const auto& q : volume_rule(type)) {
    const PointGeometry g = rule_point_geometry(type, X, q.xi);
    b_matrix(g.dNdx, B);
    const PointElastic m = point_material(mat, type, q.xi, g.N, dT);
    const Vec6 sigma_th = elasticity_matrix(m) * thermal_strain(m);
    f.noalias() += (q.weight * g.detJ) * (B.transpose() * sigma_th);
  }
}

void pressure_load(ElementType type, int face, const MatX3& X, Real p, VecX& f) {
  const std::span<const int> nodes = face_nodes(type, face);
  const Topology ftopo = face_topology(type, face);
  KONTAKT_REQUIRE(X.rows() == traits(type).n_nodes, "pressure_load: wrong number of nodes");
  f.setZero(3 * X.rows());
  ShapeVec N;
  ShapeGrad dN;
  for (const auto& q : face_rule(ftopo)) {
    shape_functions(ftopo, q.xi, N, dN);
    Vec3 ds = Vec3::Zero(), dt = Vec3::Zero();
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      ds += dN(a, 0) * X.row(nodes[a]).transpose();
      dt += dN(a, 1) * X.row(nodes[a]).transpose();
    }
    const Vec3 n_da = ds.cross(dt);  // outward normal times area element
    for (std::size_t a = 0; a < nodes.size(); ++a)
      f.segment<3>(3 * nodes[a]) -= (q.weight * p * N(a)) * n_da;
  }
}

VecX ip_volumes(ElementType type, const MatX3& X) {
  const auto rule = volume_rule(type);
  VecX v(static_cast<Index>(rule.size()));
  for (std::size_t k = 0; k < rule.size(); ++k)
    v(static_cast<Index>(k)) = rule[k].weight * rule_point_geometry(type, X, rule[k].xi).detJ;
  return v;
}

}  // namespace kontakt::element
