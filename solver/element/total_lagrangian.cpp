#include "element/total_lagrangian.hpp"

#include "element/solid_kernels.hpp"

namespace kontakt::element {

void nlgeom_element(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                    const VecX& dT, bool want_tangent, NlgeomResult& out,
                    const MatX3& modes_start) {
  auto kernel = [&](const std::vector<KernelPoint>& points, const MatX3& values, bool tangent,
                    VecX& f, MatX& K, HourglassModulus* hourglass) {
    if (hourglass) hourglass->value = points.front().material.constants.young;
    out.energy_density.resize(static_cast<Index>(points.size()));
    auto law = [&](Index k, const Mat3&, const Mat3& Fm) {
      if (mat.hyperelastic) {
        const material::HyperelasticResponse r =
            material::polynomial_hyperelastic(*mat.hyperelastic, Fm.transpose() * Fm);
        out.energy_density(k) = r.energy;
        return TotalLagrangianResponse{r.stress, r.tangent};
      }
      Vec6 e = voigt_from_tensor(0.5 * (Fm.transpose() * Fm - Mat3::Identity()));
      e.tail<3>() *= 2;  // engineering shear for D
      const Mat6 D = elasticity_matrix(points[static_cast<std::size_t>(k)].material);
      const Vec6 S = D * e;
      out.energy_density(k) = 0.5 * S.dot(e);
      return TotalLagrangianResponse{S, D};
    };
    integrate_total_lagrangian(points, values, tangent, law, f, K, out.cauchy,
                               out.green_lagrange);
  };
  run_point_kernel(type, X, mat, u, dT, modes_start, want_tangent, kernel, out.internal_force,
                   out.tangent, out.modes);
}

}  // namespace kontakt::element
