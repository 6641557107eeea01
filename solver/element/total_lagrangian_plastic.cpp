#include "element/total_lagrangian_plastic.hpp"

#include "core/error.hpp"
#include "element/solid_kernels.hpp"
#include "material/j2_finite_kinematic.hpp"

namespace kontakt::element {

namespace {

/// d C_1111 / dE_m (engineering shear) of ccx's tangent at C by central differences: the hourglass
/// modulus's derivative, for the exact tangent only (the return's second derivatives are not
/// available in closed form; ccx's tangent leaves the term out, as ccx does).
Vec6 hourglass_modulus_gradient(const LinearElastic& mat, const material::HardeningTable& hardening,
                                const material::J2State& committed, const Mat3& C) {
  static constexpr int kI[6] = {0, 1, 2, 0, 0, 1}, kJ[6] = {0, 1, 2, 1, 2, 2};
  const Real h = 1e-7;
  Vec6 g;
  for (int j = 0; j < 6; ++j) {
    Mat3 dC = Mat3::Zero();
    dC(kI[j], kJ[j]) += j < 3 ? 2 * h : h;  // dC = 2 dE, shear entries both sides
    if (j >= 3) dC(kJ[j], kI[j]) += h;
    auto c1111 = [&](const Mat3& Cp) {
      return material::j2_finite_strain(mat.young, mat.poisson, hardening, committed, Cp)
          .kirchhoff_tangent(0, 0);
    };
    g[j] = (c1111(C + dC) - c1111(C - dC)) / (2 * h);
  }
  return g;
}

/// The kinematic (or combined) return in the isotropic model's result form: its exact tangent
/// stands for both tangent choices.
material::J2FiniteResult kinematic_point(const LinearElastic& m, const material::HardeningTable& curve,
                                         const material::HardeningTable* cyclic,
                                         const material::J2State& committed, const Mat3& C) {
  const material::J2FiniteKinematicResult k =
      material::j2_finite_kinematic(m.young, m.poisson, curve, cyclic, committed, C);
  material::J2FiniteResult r;
  r.stress = k.stress;
  r.tangent = r.kirchhoff_tangent = k.tangent;
  r.state = k.state;
  r.yielded = k.yielded;
  r.delta_alpha = k.delta_alpha;
  return r;
}

}  // namespace

void nlgeom_plastic_element(ElementType type, const MatX3& X, const ThermoElastic& mat,
                            const PlasticHardening& hardening, const MatX3& u,
                            const VecX& dT, const ElementState& committed, bool want_tangent,
                            NlgeomPlasticResult& out, PlasticTangent tangent_choice) {
  auto kernel = [&](const std::vector<KernelPoint>& points, const MatX3& values, bool tangent,
                    VecX& f, MatX& K, HourglassModulus* hourglass) {
    const Index nip = static_cast<Index>(points.size());
    KONTAKT_REQUIRE(static_cast<Index>(committed.points.size()) == nip,
                    "nlgeom_plastic_element: one committed state per integration point is needed");
    out.peeq.resize(nip);
    out.energy_density.resize(nip);
    out.state.points.resize(nip);
    out.state.work.resize(nip);
    Mat3 Fm_first;  // the mechanical deformation gradient of the first point
    material::HardeningTable scratch, first_curve, cyclic_scratch;
    auto j2 = [&](Index k, const Mat3&, const Mat3& Fm) {
      const PointElastic& point = points[static_cast<std::size_t>(k)].material;
      const LinearElastic& m = point.constants;
      const material::HardeningTable& curve = hardening.curves->at(point.temperature, scratch);
      const material::J2FiniteResult r =
          hardening.rule == material::HardeningRule::Isotropic
              ? material::j2_finite_strain(m.young, m.poisson, curve, committed.points[k],
                                           Fm.transpose() * Fm)
              : kinematic_point(m, curve,
                                hardening.rule == material::HardeningRule::Combined
                                    ? &hardening.cyclic->at(point.temperature, cyclic_scratch)
                                    : nullptr,
                                committed.points[k], Fm.transpose() * Fm);
      out.peeq(k) = r.state.equivalent_plastic_strain;
      out.state.points[k] = r.state;
      const PointWork before = committed.work.empty() ? PointWork{} : committed.work[k];
      PointWork& after = out.state.work[k];
      after.stress = r.stress;
      after.strain = voigt_from_tensor(0.5 * (Fm.transpose() * Fm - Mat3::Identity()));
      const Vec6 sum = before.stress + after.stress, dE = after.strain - before.strain;
      after.density = before.density + 0.5 * (sum.head<3>().dot(dE.head<3>()) +
                                              2 * sum.tail<3>().dot(dE.tail<3>()));
      out.energy_density(k) = after.density;
      if (k == 0) {
        Fm_first = Fm;
        first_curve = curve;
        if (hourglass) hourglass->value = r.kirchhoff_tangent(0, 0);
      }
      return TotalLagrangianResponse{
          r.stress, tangent_choice == PlasticTangent::exact ? r.tangent : r.kirchhoff_tangent};
    };
    integrate_total_lagrangian(points, values, tangent, j2, f, K, out.cauchy,
                               out.green_lagrange);
    if (hourglass && tangent && tangent_choice == PlasticTangent::exact) {
      BMatrix B;
      b_nonlinear(points[0].dNdX, Fm_first, B);  // dE_m of the one point
      hourglass->gradient = B.transpose() * hourglass_modulus_gradient(
                                                points.front().material.constants, first_curve,
                                                committed.points[0],
                                                Fm_first.transpose() * Fm_first);
    }
  };
  run_point_kernel(type, X, mat, u, dT, committed.modes, want_tangent, kernel, out.internal_force,
                   out.tangent, out.state.modes);
}

}  // namespace kontakt::element
