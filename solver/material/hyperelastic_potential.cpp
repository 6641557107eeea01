#include "material/hyperelastic_potential.hpp"

namespace kontakt::material {

HyperelasticResponse hyperelastic_response(const HyperelasticPotential& potential, const Mat3& C) {
  struct Evaluate {
    const Mat3& C;
    HyperelasticResponse operator()(const HyperelasticPolynomial& p) const {
      return polynomial_hyperelastic(p, C);
    }
    HyperelasticResponse operator()(const Ogden& p) const { return ogden_hyperelastic(p, C); }
    HyperelasticResponse operator()(const Hyperfoam& p) const { return hyperfoam(p, C); }
  };
  return std::visit(Evaluate{C}, potential);
}

}  // namespace kontakt::material
