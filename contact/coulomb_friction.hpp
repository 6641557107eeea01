// Coulomb friction of one contact point with an elastic stick range (thesis section 3.2,
// figure 19; ccx-behaviour.md section 1.4; friction.md section 2.1): the tangential force
// follows the tangential relative displacement with slope k_t = lambda * A up to mu |F_N|,
// where it slips. A radial return from the increment's start state:
//   t    = t_start + (I - n n^T) s            accumulated tangential relative displacement
//   F_tr = k_t (I - n n^T)(t - t_slip,start)  elastic predictor (in the current tangent plane)
//   stick when |F_tr| <= mu F_N:  F_T = F_tr
//   slip otherwise:               F_T = mu F_N xi,  xi = F_tr / |F_tr|,
//                                 t_slip = t_slip,start + (|F_tr| - mu F_N) / k_t xi
// s is the relative displacement (slave minus master point) since the increment's start and
// n the normal, frozen for the increment. F_T acts on the slave point (on the master with the
// opposite sign) as an internal force: f_int = B^T F_T with a = B u. Pure functions.
#pragma once

#include "core/types.hpp"

namespace kontakt::contact {

/// What a point carries from one converged increment to the next (global components).
struct FrictionState {
  Vec3 tangential = Vec3::Zero();  ///< t: accumulated tangential relative displacement
  Vec3 slip = Vec3::Zero();        ///< t_slip: its irreversible part
};

struct CoulombLaw {
  Real mu = 0;           ///< friction coefficient; infinite for tied contact (never slips)
  Real stick_slope = 0;  ///< lambda: shear stress per unit tangential displacement
};

struct TangentialResponse {
  Vec3 force = Vec3::Zero();       ///< F_T
  Mat3 d_force_d_s = Mat3::Zero();  ///< dF_T / ds
  Vec3 d_force_d_normal = Vec3::Zero();  ///< dF_T / dF_N (nonzero in slip only)
  FrictionState state;             ///< trial state at this s
  bool slipping = false;
};

/// The tangential response of a point of area `area` pressed with the normal force
/// `normal_force` (F_N = A p; a point that does not press carries no shear and relaxes its
/// elastic stretch, with the stick tangent while it has none: ccx's zero trial force sticks),
/// from its state at the start of the increment.
TangentialResponse coulomb_response(const CoulombLaw& law, const FrictionState& start,
                                    const Vec3& s, const Vec3& normal, Real area,
                                    Real normal_force);

}  // namespace kontakt::contact
