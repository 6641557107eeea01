#include "element/solid_plastic.hpp"

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

void plastic_element(ElementType type, const MatX3& X, const LinearElastic& mat,
                     const material::HardeningTable& hardening, const MatX3& u, const VecX& dT,
                     const std::vector<material::J2State>& committed, bool want_tangent,
                     PlasticResult& out) {
  if (type == ElementType::C3D8I)
    throw SolverError("C3D8I is not available with *PLASTIC yet; use C3D8, C3D20R or C3D20");
  const int n = static_cast<int>(X.rows());
  const auto rule = volume_rule(type);
  const Index nip = static_cast<Index>(rule.size());
  KONTAKT_REQUIRE(static_cast<Index>(committed.size()) == nip,
                  "plastic_element: one committed state per integration point is needed");
  const VecX temp = dT.size() == n ? dT : VecX::Zero(n);
  const Eigen::Map<const VecX> ue(u.data(), u.size());
  out.internal_force.setZero(3 * n);
  if (want_tangent) out.tangent.setZero(3 * n, 3 * n);
  out.stress.resize(nip, 6);
  out.strain.resize(nip, 6);
  out.peeq.resize(nip);
  out.energy_density.resize(nip);
  out.state.resize(nip);
  BMatrix B;
  for (Index k = 0; k < nip; ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    b_matrix(g.dNdx, B);
    const Vec6 eps = B * ue;  // engineering shear
    const Real thermal = mat.expansion * point_temperature(type, rule[k].xi, g.N, temp);
    const material::J2Result r = material::j2_return_map(mat.young, mat.poisson, hardening,
                                                         committed[k], eps, thermal);
    const Real dv = rule[k].weight * g.detJ;
    out.internal_force.noalias() += dv * (B.transpose() * r.stress);
    if (want_tangent) out.tangent.noalias() += dv * (B.transpose() * r.tangent * B);
    out.stress.row(k) = r.stress.transpose();
    out.strain.row(k) = tensor_strain(eps).transpose();
    out.peeq(k) = r.state.equivalent_plastic_strain;
    Vec6 elastic = tensor_strain(eps) - r.state.plastic_strain;
    elastic.head<3>().array() -= thermal;
    elastic.tail<3>() *= 2;
    out.energy_density(k) = 0.5 * r.stress.dot(elastic);
    out.state[k] = r.state;
  }
  if (type == ElementType::C3D8R) {
    MatX Khg;
    hourglass_stiffness(X, mat, Khg);
    out.internal_force += Khg * ue;
    if (want_tangent) out.tangent += Khg;
  }
}

}  // namespace kontakt::element
