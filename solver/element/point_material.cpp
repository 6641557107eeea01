// The thermo-elastic material of an integration point: tables evaluated at its temperature.
#include "element/solid_kernels.hpp"
#include "element/solid_linear.hpp"
#include "material/anisotropic_elastic.hpp"

namespace kontakt::element {

ThermoElastic::ThermoElastic(const LinearElastic& constant) {
  elastic.add(0, {constant.young, constant.poisson});
  if (constant.expansion != 0) expansion.add(0, {constant.expansion});
}

PointElastic ThermoElastic::at(Real T0, Real dT, const Vec3& x) const {
  const Real T = T0 + dT;
  PointElastic p;
  p.temperature = T;
  if (!anisotropic.empty()) {
    const Mat6 local = material::anisotropic_stiffness(anisotropic.at(T));
    p.stiffness = frame ? material::rotate_stiffness(local, frame(x)) : local;
  } else if (!elastic.empty()) {  // empty for hyperelastic and deformation plasticity
    const auto [young, poisson] = elastic.at(T);
    p.constants.young = young;
    p.constants.poisson = poisson;
  }
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
  // The point's position matters only to a frame that varies (cylindrical orientation).
  const Vec3 x = mat.frame ? Vec3(mat.coords.transpose() * N.head(mat.coords.rows()))
                           : Vec3::Zero();
  return mat.at(point_temperature(type, xi, N, mat.initial_temperature),
                point_temperature(type, xi, N, dT), x);
}

}  // namespace kontakt::element
