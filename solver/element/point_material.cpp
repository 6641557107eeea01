// The thermo-elastic material of an integration point: tables evaluated at its temperature.
#include "element/solid_kernels.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {

ThermoElastic::ThermoElastic(const LinearElastic& constant) {
  elastic.add(0, {constant.young, constant.poisson});
  if (constant.expansion != 0) expansion.add(0, {constant.expansion});
}

PointElastic ThermoElastic::at(Real T0, Real dT) const {
  const Real T = T0 + dT;
  const auto [young, poisson] = elastic.at(T);
  PointElastic p{{young, poisson, 0}, 0, T};
  if (expansion.empty()) return p;
  p.constants.expansion = expansion.at(T)[0];
  // A table's secant coefficient refers to ZERO; one row is the same coefficient at every T.
  p.thermal_strain = expansion.rows.size() == 1
                         ? p.constants.expansion * dT
                         : p.constants.expansion * (T - expansion_zero) -
                               expansion.at(T0)[0] * (T0 - expansion_zero);
  return p;
}

PointElastic point_material(const ThermoElastic& mat, ElementType type, const Vec3& xi,
                            const ShapeVec& N, const VecX& dT) {
  return mat.at(point_temperature(type, xi, N, mat.initial_temperature),
                point_temperature(type, xi, N, dT));
}

}  // namespace kontakt::element
