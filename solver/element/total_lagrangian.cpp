#include "element/total_lagrangian.hpp"

#include <Eigen/LU>

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

namespace {

/// 6 x 3n nonlinear strain-displacement matrix: dE (engineering shear) = B_NL du.
void b_nonlinear(const ShapeGrad& dNdX, const Mat3& F, BMatrix& B) {
  const int n = static_cast<int>(dNdX.rows());
  B.setZero(6, 3 * n);
  for (int a = 0; a < n; ++a) {
    const Real g0 = dNdX(a, 0), g1 = dNdX(a, 1), g2 = dNdX(a, 2);
    for (int k = 0; k < 3; ++k) {
      B(0, 3 * a + k) = F(k, 0) * g0;
      B(1, 3 * a + k) = F(k, 1) * g1;
      B(2, 3 * a + k) = F(k, 2) * g2;
      B(3, 3 * a + k) = F(k, 0) * g1 + F(k, 1) * g0;
      B(4, 3 * a + k) = F(k, 0) * g2 + F(k, 2) * g0;
      B(5, 3 * a + k) = F(k, 1) * g2 + F(k, 2) * g1;
    }
  }
}

Mat3 tensor_from_voigt(const Vec6& s) {
  Mat3 t;
  t << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
  return t;
}

Vec6 voigt_from_tensor(const Mat3& t) {
  Vec6 v;
  v << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(0, 2), t(1, 2);
  return v;
}

}  // namespace

void nlgeom_element(ElementType type, const MatX3& X, const LinearElastic& mat, const MatX3& u,
                    const VecX& dT, bool want_tangent, NlgeomResult& out) {
  if (type == ElementType::C3D8I)
    throw SolverError("C3D8I is not available with NLGEOM yet; use C3D8, C3D20R or C3D20");
  const int n = static_cast<int>(X.rows());
  KONTAKT_REQUIRE(u.rows() == n, "nlgeom_element: wrong number of displacements");
  const VecX temp = dT.size() == n ? dT : VecX::Zero(n);
  const auto rule = volume_rule(type);
  const Index nip = static_cast<Index>(rule.size());
  const Mat6 D = elasticity_matrix(mat);
  out.internal_force.setZero(3 * n);
  if (want_tangent) out.tangent.setZero(3 * n, 3 * n);
  out.cauchy.resize(nip, 6);
  out.green_lagrange.resize(nip, 6);
  out.energy_density.resize(nip);
  BMatrix B;
  for (Index k = 0; k < nip; ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    const Mat3 F = Mat3::Identity() + u.transpose() * g.dNdx;  // F_ij = d_ij + du_i/dX_j
    const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
    Vec6 e = voigt_from_tensor(E);
    out.green_lagrange.row(k) = e.transpose();
    e.tail<3>() *= 2;  // engineering shear for D
    const Vec6 e_mech = e - thermal_strain(mat, point_temperature(type, rule[k].xi, g.N, temp));
    const Vec6 S = D * e_mech;
    const Mat3 S_t = tensor_from_voigt(S);
    const Real J = F.determinant();
    if (!(J > 0)) throw SolverError("the element is inverted (det F <= 0)");
    out.cauchy.row(k) = voigt_from_tensor(F * S_t * F.transpose() / J).transpose();
    out.energy_density(k) = 0.5 * S.dot(e_mech);
    b_nonlinear(g.dNdx, F, B);
    const Real dv = rule[k].weight * g.detJ;
    out.internal_force.noalias() += dv * (B.transpose() * S);
    if (want_tangent) {
      out.tangent.noalias() += dv * (B.transpose() * D * B);
      const MatX G = g.dNdx * S_t * g.dNdx.transpose();  // n x n initial-stress terms
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
          for (int c = 0; c < 3; ++c) out.tangent(3 * a + c, 3 * b + c) += dv * G(a, b);
    }
  }
  if (type == ElementType::C3D8R) {
    MatX Khg;
    hourglass_stiffness(X, mat, Khg);
    out.internal_force += Khg * Eigen::Map<const VecX>(u.data(), u.size());
    if (want_tangent) out.tangent += Khg;
  }
}

}  // namespace kontakt::element
