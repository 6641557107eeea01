#include "contact/coulomb_friction.hpp"

#include <cmath>

namespace kontakt::contact {

TangentialResponse coulomb_response(const CoulombLaw& law, const FrictionState& start,
                                    const Vec3& s, const Vec3& normal, Real area,
                                    Real normal_force) {
  TangentialResponse r;
  const Mat3 P = Mat3::Identity() - normal * normal.transpose();
  r.state.tangential = start.tangential + P * s;
  const bool tied = !std::isfinite(law.mu);  // sticks whatever the normal force
  const Real k_t = law.stick_slope * area;
  // The state was tangent to the normal of an earlier increment: only its part in the current
  // tangent plane is stretch (else the shear gets a normal part and |q| < mu p in slip).
  const Vec3 elastic = P * (r.state.tangential - start.slip);
  if (!(normal_force > 0) && !tied) {
    // Touching without pressure (or in a law's tension tail): no shear; the elastic stretch
    // goes, the slip stays. Not yet stretched, it sticks with zero force (ccx: a zero trial
    // force sticks), so bodies held only by friction are no mechanism before they press.
    r.state.slip = r.state.tangential;
    if (elastic.isZero(0)) r.d_force_d_s = k_t * P;
    return r;
  }
  const Vec3 trial = k_t * elastic;
  const Real trial_norm = trial.norm();
  const Real limit = tied ? trial_norm : law.mu * normal_force;
  if (trial_norm <= limit) {
    r.force = trial;
    r.d_force_d_s = k_t * P;
    r.state.slip = start.slip;
    return r;
  }
  const Vec3 xi = trial / trial_norm;
  r.slipping = true;
  r.force = limit * xi;
  // d xi / d s = (I - xi xi^T) / |elastic| * P
  r.d_force_d_s = limit / elastic.norm() * (Mat3::Identity() - xi * xi.transpose()) * P;
  r.d_force_d_normal = law.mu * xi;
  r.state.slip = start.slip + (trial_norm - limit) / k_t * xi;
  return r;
}

}  // namespace kontakt::contact
