#include "element/total_lagrangian_plastic.hpp"

#include "core/error.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

void nlgeom_plastic_element(ElementType type, const MatX3& X, const LinearElastic& mat,
                            const material::HardeningTable& hardening, const MatX3& u,
                            const VecX& dT, const ElementState& committed, bool want_tangent,
                            NlgeomPlasticResult& out, PlasticTangent tangent_choice) {
  auto kernel = [&](const std::vector<KernelPoint>& points, const MatX3& values, bool tangent,
                    VecX& f, MatX& K) {
    const Index nip = static_cast<Index>(points.size());
    KONTAKT_REQUIRE(static_cast<Index>(committed.points.size()) == nip,
                    "nlgeom_plastic_element: one committed state per integration point is needed");
    out.peeq.resize(nip);
    out.energy_density.resize(nip);
    out.state.points.resize(nip);
    auto j2 = [&](Index k, const Mat3&, const Mat3& Fm) {
      const material::J2FiniteResult r = material::j2_finite_strain(
          mat.young, mat.poisson, hardening, committed.points[k], Fm.transpose() * Fm);
      out.peeq(k) = r.state.equivalent_plastic_strain;
      out.energy_density(k) = r.energy_density;
      out.state.points[k] = r.state;
      return TotalLagrangianResponse{
          r.stress, tangent_choice == PlasticTangent::exact ? r.tangent : r.kirchhoff_tangent};
    };
    integrate_total_lagrangian(points, values, mat.expansion, tangent, j2, f, K, out.cauchy,
                               out.green_lagrange);
  };
  run_point_kernel(type, X, mat, u, dT, committed.modes, want_tangent, kernel, out.internal_force,
                   out.tangent, out.state.modes);
}

}  // namespace kontakt::element
