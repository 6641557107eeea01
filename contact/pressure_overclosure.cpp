#include "contact/pressure_overclosure.hpp"

#include <algorithm>
#include <cmath>

namespace kontakt::contact {

namespace {
/// The exponential law continues linearly beyond exp(kExpCap), so huge overclosures in a
/// diverging iteration stay finite (ccx caps the exponent near e^23 as well).
constexpr Real kExpCap = 23;
}  // namespace

PressureLaw make_pressure_law(const model::SurfaceBehavior& b, bool linear_variant) {
  using Law = model::SurfaceBehavior::Law;
  PressureLaw law;
  law.stiffness = b.stiffness;
  switch (b.law) {
    case Law::Linear:
      law.kind = linear_variant || b.tension_limit <= 0 ? PressureLaw::Kind::Linear
                                                        : PressureLaw::Kind::QuasiBilinear;
      law.eps = M_PI * b.tension_limit / law.stiffness;
      break;
    case Law::Exponential:
      law.kind = PressureLaw::Kind::Exponential;
      law.p0 = b.exp_p0;
      law.beta = std::log(100.0) / b.exp_c0;
      break;
    case Law::Tabular:
      law.kind = PressureLaw::Kind::Tabular;
      law.table = b.table;
      break;
    case Law::Tied: law.kind = PressureLaw::Kind::Tied; break;
  }
  return law;
}

PressureResponse pressure_overclosure(const PressureLaw& law, Real d) {
  PressureResponse r;
  const Real K = law.stiffness;
  switch (law.kind) {
    case PressureLaw::Kind::Linear:
      // Touching (d = 0) counts as contact: no force yet, but the penalty stiffness.
      if (d >= 0) r = {K * d, K, 0.5 * K * d * d};
      return r;
    case PressureLaw::Kind::Tied: return {K * d, K, 0.5 * K * d * d};
    case PressureLaw::Kind::QuasiBilinear: {
      const Real e = law.eps, s = d / e, at = std::atan(s);
      r.pressure = K * d * (0.5 + at / M_PI);
      r.slope = K * (0.5 + at / M_PI) + K * s / (M_PI * (1 + s * s));
      // integral of K x (1/2 + atan(x/e)/pi) dx from 0 to d
      r.energy = K * (0.25 * d * d + (0.5 * d * d * at - 0.5 * e * (d - e * at)) / M_PI);
      return r;
    }
    case PressureLaw::Kind::Exponential: {
      const Real x = law.beta * d;
      const Real xc = std::min(x, kExpCap), ex = std::exp(xc);
      r.pressure = law.p0 * ex * (1 + (x - xc));
      r.slope = law.p0 * law.beta * ex;
      r.energy = law.p0 / law.beta * (ex - 1) + law.p0 * ex * (x - xc) * (1 + 0.5 * (x - xc)) / law.beta;
      return r;
    }
    case PressureLaw::Kind::Tabular: {
      const auto& t = law.table;
      if (t.empty()) return r;
      if (d <= t.front().first) {
        r.pressure = t.front().second;
        r.energy = r.pressure * d;
        return r;
      }
      Real energy = t.front().second * t.front().first;
      for (std::size_t i = 1; i < t.size(); ++i) {
        const auto [d0, p0] = t[i - 1];
        const auto [d1, p1] = t[i];
        const Real slope = (p1 - p0) / (d1 - d0);
        if (d <= d1) {
          r.pressure = p0 + slope * (d - d0);
          r.slope = slope;
          r.energy = energy + 0.5 * (p0 + r.pressure) * (d - d0);
          return r;
        }
        energy += 0.5 * (p0 + p1) * (d1 - d0);
      }
      r.pressure = t.back().second;
      r.energy = energy + r.pressure * (d - t.back().first);
      return r;
    }
  }
  return r;
}

bool is_active(const PressureLaw& law, Real d, Real clearance) {
  switch (law.kind) {
    case PressureLaw::Kind::Linear: return d >= 0;
    case PressureLaw::Kind::Tied: return true;
    default: return d >= -clearance;
  }
}

Real reference_stiffness(const PressureLaw& law) {
  switch (law.kind) {
    case PressureLaw::Kind::Exponential: return law.p0 * law.beta;
    case PressureLaw::Kind::Tabular: {
      Real k = 0;
      for (std::size_t i = 1; i < law.table.size(); ++i)
        k = std::max(k, (law.table[i].second - law.table[i - 1].second) /
                            (law.table[i].first - law.table[i - 1].first));
      return k;
    }
    default: return law.stiffness;
  }
}

Real creation_clearance(const model::SurfaceBehavior& b, Real area) {
  using Law = model::SurfaceBehavior::Law;
  if (b.law == Law::Exponential) return b.exp_c0;
  return area > 0 ? b.clearance_c0 * std::sqrt(area) : 1e-10;
}

}  // namespace kontakt::contact
