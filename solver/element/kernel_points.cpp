#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

std::vector<KernelPoint> kernel_points(ElementType type, const MatX3& X, const ThermoElastic& mat,
                                       const VecX& dT) {
  const auto rule = volume_rule(type);
  KONTAKT_REQUIRE(dT.size() == 0 || dT.size() == X.rows(),
                  "kernel_points: one temperature change per node is needed");
  std::vector<KernelPoint> points(rule.size());
  for (std::size_t k = 0; k < rule.size(); ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    points[k] = {g.dNdx, rule[k].weight * g.detJ, point_material(mat, type, rule[k].xi, g.N, dT)};
  }
  return points;
}

void run_point_kernel(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                      const VecX& dT,
                      const MatX3& modes_start, bool want_tangent, const PointKernel& kernel,
                      VecX& f, MatX& K, MatX3& modes) {
  KONTAKT_REQUIRE(u.rows() == X.rows(), "element kernel: wrong number of displacements");
  const VecX temp = dT.size() == X.rows() ? dT : VecX();
  if (type == ElementType::C3D8I) {
    const auto points = incompatible_kernel_points(X, mat, temp);
    const Mat3 R = incompatible_frame_rotation(X, u);  // amplitudes are rows: a^T R^T = (R a)^T
    const MatX3 start = modes_start.size() ? MatX3(modes_start * R.transpose()) : MatX3();
    const Real size = (X.colwise().maxCoeff() - X.colwise().minCoeff()).maxCoeff();
    condense_incompatible_modes(
        u, start, size,
        [&](const MatX3& values, VecX& fa, MatX& Ka) {
          kernel(points, values, true, fa, Ka, nullptr);
        },
        want_tangent, f, K, modes);
    modes = modes * R;
    return;
  }
  modes.resize(0, 3);
  if (type != ElementType::C3D8R) {
    kernel(kernel_points(type, X, mat, temp), u, want_tangent, f, K, nullptr);
    return;
  }
  HourglassModulus modulus;
  kernel(kernel_points(type, X, mat, temp), u, want_tangent, f, K, &modulus);
  MatX unit;
  hourglass_stiffness(X, 1.0, unit);
  const VecX f_unit = unit * Eigen::Map<const VecX>(u.data(), u.size());
  f += modulus.value * f_unit;
  if (!want_tangent) return;
  K += modulus.value * unit;
  if (modulus.gradient.size()) K += f_unit * modulus.gradient.transpose();
}

}  // namespace kontakt::element
