#include "analysis/truss.hpp"

namespace kontakt::analysis {

namespace {

/// (xx, yy, zz, xy, xz, yz) of a symmetric matrix; + 0.0 prints a zero product as 0, not -0.
Vec6 components(const Mat3& m) {
  Vec6 v;
  v << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2);
  return v.array() + 0.0;
}

/// The strain of a bar stretched by `eps` along unit axis `A` with free lateral faces.
Mat3 uniaxial_strain(const Vec3& A, Real eps, Real poisson) {
  const Mat3 AA = A * A.transpose();
  return eps * (AA - poisson * (Mat3::Identity() - AA));
}

}  // namespace

AxialForce truss_axial_force(const model::Connector& c, Real length0, Real elongation,
                             bool nlgeom) {
  const Real EA = c.young * c.area;
  if (!nlgeom)
    return {EA / length0 * elongation, EA / length0,
            0.5 * EA / length0 * elongation * elongation};
  const Real stretch = (length0 + elongation) / length0;
  const Real green = 0.5 * (stretch * stretch - 1);
  // dN/de = E A (E_11 + lambda^2) / L, from dE_11/de = lambda / L
  return {EA * stretch * green, EA * (green + stretch * stretch) / length0,
          0.5 * EA * length0 * green * green};
}

TrussPointOutput truss_point_output(const model::Connector& c, const Vec3& X1, const Vec3& X2,
                                    const Vec3& u1, const Vec3& u2, bool nlgeom) {
  const Vec3 L0 = X2 - X1;
  const Real length0 = L0.norm();
  const Vec3 A = L0 / length0;
  TrussPointOutput out;
  if (!nlgeom) {
    const Real eps = A.dot(u2 - u1) / length0;
    out.stress = components(c.young * eps * A * A.transpose());
    out.strain = components(uniaxial_strain(A, eps, c.poisson));
    out.energy_density = 0.5 * c.young * eps * eps;
    return out;
  }
  const Vec3 d = L0 + u2 - u1;
  const Real stretch = d.norm() / length0;
  const Real green = 0.5 * (stretch * stretch - 1);
  const Vec3 a = d.normalized();
  const Real sigma = c.young * green * stretch / (1 - 2 * c.poisson * green);
  out.stress = components(sigma * a * a.transpose());
  out.strain = components(uniaxial_strain(A, green, c.poisson));
  out.energy_density = 0.5 * c.young * green * green;
  return out;
}

}  // namespace kontakt::analysis
