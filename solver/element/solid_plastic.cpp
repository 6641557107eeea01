#include "element/solid_plastic.hpp"

#include "core/error.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

void plastic_element(ElementType type, const MatX3& X, const ThermoElastic& mat,
                     const material::HardeningCurves& hardening, const MatX3& u, const VecX& dT,
                     const ElementState& committed, bool want_tangent, PlasticResult& out) {
  auto kernel = [&](const std::vector<KernelPoint>& points, const MatX3& values, bool tangent,
                    VecX& f, MatX& K, HourglassModulus* hourglass) {
    if (hourglass) hourglass->value = points.front().material.constants.young;  // small strain: the linear element's
    const int n = static_cast<int>(values.rows());
    const Index nip = static_cast<Index>(points.size());
    KONTAKT_REQUIRE(static_cast<Index>(committed.points.size()) == nip,
                    "plastic_element: one committed state per integration point is needed");
    const Eigen::Map<const VecX> ue(values.data(), values.size());
    f.setZero(3 * n);
    if (tangent) K.setZero(3 * n, 3 * n);
    out.stress.resize(nip, 6);
    out.strain.resize(nip, 6);
    out.peeq.resize(nip);
    out.energy_density.resize(nip);
    out.state.points.resize(nip);
    BMatrix B;
    material::HardeningTable scratch;
    for (Index k = 0; k < nip; ++k) {
      const KernelPoint& p = points[k];
      b_matrix(p.dNdX, B);
      const Vec6 eps = B * ue;  // engineering shear
      const Real thermal = p.material.thermal_strain;
      const LinearElastic& m = p.material.constants;
      const material::J2Result r = material::j2_return_map(m.young, m.poisson,
                                                           hardening.at(p.material.temperature, scratch),
                                                           committed.points[k], eps, thermal);
      f.noalias() += p.dv * (B.transpose() * r.stress);
      if (tangent) K.noalias() += p.dv * (B.transpose() * r.tangent * B);
      out.stress.row(k) = r.stress.transpose();
      out.strain.row(k) = tensor_strain(eps).transpose();
      out.peeq(k) = r.state.equivalent_plastic_strain;
      Vec6 elastic = tensor_strain(eps) - r.state.plastic_strain;
      elastic.head<3>().array() -= thermal;
      elastic.tail<3>() *= 2;
      out.energy_density(k) = 0.5 * r.stress.dot(elastic);
      out.state.points[k] = r.state;
    }
  };
  run_point_kernel(type, X, mat, u, dT, committed.modes, want_tangent, kernel, out.internal_force,
                   out.tangent, out.state.modes);
}

}  // namespace kontakt::element
