#include "element/initial_stress.hpp"

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

void initial_stress_force(ElementType type, const MatX3& X, const MatX& sigma0, VecX& f) {
  KONTAKT_REQUIRE(type != ElementType::C3D8I, "initial stress: C3D8I is not supported");
  const auto rule = volume_rule(type);
  KONTAKT_REQUIRE(sigma0.rows() == static_cast<Index>(rule.size()) && sigma0.cols() == 6,
                  "initial stress: one row of 6 components per integration point expected");
  f.setZero(3 * X.rows());
  BMatrix B;
  for (std::size_t k = 0; k < rule.size(); ++k) {
    const PointGeometry g = rule_point_geometry(type, X, rule[k].xi);
    b_matrix(g.dNdx, B);
    // Engineering-shear B pairs with the tensor shear stresses: sigma : eps = sigma^T B u.
    const Vec6 s = sigma0.row(static_cast<Index>(k)).transpose();
    f.noalias() += (rule[k].weight * g.detJ) * (B.transpose() * s);
  }
}

}  // namespace kontakt::element
