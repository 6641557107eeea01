#include "analysis/connector.hpp"

#include <cmath>

#include "analysis/truss.hpp"
#include "contact/pressure_overclosure.hpp"

namespace kontakt::analysis {

namespace {

/// Force and slope of a spring at elongation `e`: linear, or through the curve with constant
/// ends (zero slope there); the energy from elongation 0, piecewise along the curve.
AxialForce spring_force(const model::Connector& c, Real e) {
  if (c.curve.empty()) return {c.stiffness * e, c.stiffness, 0.5 * c.stiffness * e * e};
  const auto& t = c.curve;
  auto at = [&](Real x) {  // force at elongation x, constant beyond the ends
    if (x <= t.front().first) return t.front().second;
    if (x >= t.back().first) return t.back().second;
    std::size_t k = 1;
    while (t[k].first < x) ++k;
    const Real w = (x - t[k - 1].first) / (t[k].first - t[k - 1].first);
    return t[k - 1].second + w * (t[k].second - t[k - 1].second);
  };
  AxialForce s;
  s.force = at(e);
  for (std::size_t k = 1; k < t.size(); ++k)  // segments [x_k-1, x_k): a kink takes the right
    if (e >= t[k - 1].first && e < t[k].first)
      s.slope = (t[k].second - t[k - 1].second) / (t[k].first - t[k - 1].first);
  // energy: trapezoids from elongation 0 to e over the curve's breakpoints
  Real a = 0;
  const Real lo = std::min<Real>(0, e), hi = std::max<Real>(0, e);
  std::vector<Real> xs{lo, hi};
  for (const auto& [x, f] : t)
    if (x > lo && x < hi) xs.push_back(x);
  std::sort(xs.begin(), xs.end());
  for (std::size_t k = 1; k < xs.size(); ++k)
    a += 0.5 * (at(xs[k - 1]) + at(xs[k])) * (xs[k] - xs[k - 1]);
  s.energy = e >= 0 ? a : -a;
  return s;
}

/// The 6 x 6 stiffness of a pair from the 3 x 3 block k22 that node 2 sees.
Eigen::Matrix<Real, 6, 6> pair_stiffness(const Mat3& k) {
  Eigen::Matrix<Real, 6, 6> K;
  K << k, -k, -k, k;
  return K;
}

}  // namespace

ConnectorResponse connector_response(const model::Connector& c, const Vec3& X1, const Vec3& X2,
                                     const Vec3& u1, const Vec3& u2, bool nlgeom) {
  ConnectorResponse r;
  if (c.kind == model::Connector::Kind::Gap) {
    const Vec3& n = c.direction;
    const Real overclosure = -(c.clearance + n.dot(u2 - u1));
    contact::PressureLaw law;  // ccx: the node-to-face spring of the linear law
    law.kind = contact::PressureLaw::Kind::QuasiBilinear;
    law.stiffness = c.stiffness;
    law.eps = M_PI * c.tension / c.stiffness;
    const contact::PressureResponse p = contact::pressure_overclosure(law, overclosure);
    // Internal forces: the gap pushes node 2 back along n with p, node 1 against it.
    r.force << p.pressure * n, -p.pressure * n;
    r.stiffness = pair_stiffness(p.slope * n * n.transpose());
    r.energy = p.energy;
    return r;
  }
  const Vec3 L0 = X2 - X1;
  const Real length0 = L0.norm();
  // Springs and trusses are the same axial member: only their force against elongation differs.
  const auto axial_force = [&](Real elongation) {
    return c.kind == model::Connector::Kind::Truss ? truss_axial_force(c, length0, elongation, nlgeom)
                                                   : spring_force(c, elongation);
  };
  if (!nlgeom) {  // small displacements: the initial direction
    const Vec3 n = L0 / length0;
    const AxialForce s = axial_force(n.dot(u2 - u1));
    r.force << -s.force * n, s.force * n;
    r.stiffness = pair_stiffness(s.slope * n * n.transpose());
    r.energy = s.energy;
    return r;
  }
  const Vec3 d = L0 + u2 - u1;
  const Real length = d.norm();
  if (!(length > 0))
    throw SolverError(std::string(model::connector_type_name(c.kind)) + " element " +
                      std::to_string(c.id) +
                      " has collapsed to a point: its direction is undefined");
  const Vec3 n = d / length;
  const AxialForce s = axial_force(length - length0);
  r.force << -s.force * n, s.force * n;
  const Mat3 nn = n * n.transpose();
  r.stiffness = pair_stiffness(s.slope * nn + s.force / length * (Mat3::Identity() - nn));
  r.energy = s.energy;
  return r;
}

}  // namespace kontakt::analysis
