// Integration-point results of the linear solid elements: strain, stress, energy, nodal forces.
#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {
namespace {

// Engineering total strain at every point (n_ip x 6).
MatX6 point_strains(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                    const VecX& dT) {
  const auto rule = volume_rule(type);
  MatX6 eps(static_cast<Index>(rule.size()), 6);
  if (type == ElementType::C3D8I) {
    Eigen::Matrix<Real, 8, 6> e;
    incompatible_strains(X, mat, u, dT, e);
    eps = e;
    return eps;
  }
  BMatrix B;
  const Eigen::Map<const VecX> ue(u.data(), u.size());  // row-major: node-major DOFs
  for (std::size_t k = 0; k < rule.size(); ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    b_matrix(g.dNdx, B);
    eps.row(static_cast<Index>(k)) = (B * ue).transpose();
  }
  return eps;
}

}  // namespace

void recover(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
             const VecX& dT, IpResults& out) {
  const Topology topo = volume_topology(type);
  const int n = node_count(topo);
  KONTAKT_REQUIRE(X.rows() == n && u.rows() == n, "recover: wrong number of nodes");
  const VecX temp = dT.size() == n ? dT : VecX::Zero(n);
  const auto rule = volume_rule(type);
  const Index nip = static_cast<Index>(rule.size());
  const MatX6 eps = point_strains(type, X, mat, u, temp);
  out.stress.resize(nip, 6);
  out.strain.resize(nip, 6);
  out.energy_density.resize(nip);
  out.internal_force.setZero(3 * n);
  out.volume = 0;
  BMatrix B;
  Real hourglass_modulus = 0;  // C3D8R: its one point's
  for (Index k = 0; k < nip; ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    const PointElastic m = point_material(mat, type, rule[k].xi, g.N, temp);
    hourglass_modulus = m.constants.young;
    const Vec6 e = eps.row(k).transpose();
    const Vec6 e_el = e - thermal_strain(m);
    const Vec6 s = elasticity_matrix(m) * e_el;
    out.stress.row(k) = s.transpose();
    out.strain.row(k) = tensor_strain(e).transpose();
    out.energy_density(k) = 0.5 * s.dot(e_el);
    b_matrix(g.dNdx, B);
    const Real dv = rule[k].weight * g.detJ;
    out.internal_force.noalias() += dv * (B.transpose() * s);
    out.volume += dv;
  }
  if (type == ElementType::C3D8R) {
    MatX Khg;
    hourglass_stiffness(X, hourglass_modulus, Khg);
    out.internal_force += Khg * Eigen::Map<const VecX>(u.data(), u.size());
  }
}

}  // namespace kontakt::element
