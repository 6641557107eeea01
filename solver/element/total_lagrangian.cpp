#include "element/total_lagrangian.hpp"

#include <Eigen/LU>

#include "element/solid_kernels.hpp"

namespace kontakt::element {

void nlgeom_element(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                    const VecX& dT, bool want_tangent, NlgeomResult& out,
                    const MatX3& modes_start) {
  auto kernel = [&](const std::vector<KernelPoint>& points, const MatX3& values, bool tangent,
                    VecX& f, MatX& K, HourglassModulus* hourglass) {
    if (hourglass) hourglass->value = points.front().material.constants.young;
    out.energy_density.resize(static_cast<Index>(points.size()));
    MatX6 eulerian(static_cast<Index>(points.size()), 6);
    auto law = [&](Index k, const Mat3& F, const Mat3& Fm) {
      if (mat.deformation_plasticity) {
        const material::DeformationPlasticityResponse r =
            material::deformation_plasticity(*mat.deformation_plasticity, Fm);
        const Mat3 Fi = F.inverse();  // the printed strain: Eulerian, e = F^-T E F^-1
        eulerian.row(k) =
            voigt_from_tensor(0.5 * Fi.transpose() * (F.transpose() * F - Mat3::Identity()) * Fi)
                .transpose();
        // No stored energy: the reader refuses ENER and ELSE requests for this material.
        out.energy_density(k) = 0;
        return TotalLagrangianResponse{r.stress, r.tangent};
      }
      if (mat.hyperelastic) {
        const material::HyperelasticResponse r =
            material::hyperelastic_response(*mat.hyperelastic, Fm.transpose() * Fm);
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
    // ccx prints the Eulerian strain its deformation plasticity law works with.
    if (mat.deformation_plasticity) out.green_lagrange = eulerian;
  };
  run_point_kernel(type, X, mat, u, dT, modes_start, want_tangent, kernel, out.internal_force,
                   out.tangent, out.modes);
}

}  // namespace kontakt::element
