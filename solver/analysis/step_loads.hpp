// What a step prescribes at a given time: external nodal forces, prescribed displacement
// values and the temperature field. Loads without an amplitude take their full value at the
// step end (linear analysis) or ramp from the previous step's end values (nonlinear).
#pragma once

#include <vector>

#include "assembly/dof_map.hpp"
#include "element/body_load.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// The amplitude's factor at a time (1 when `amplitude` is -1).
Real amplitude_factor(const model::Model& model, int amplitude, Real step_time, Real total_time);

/// Nodal forces (3 * n_nodes) of *CLOAD and *DLOAD. Loads with an amplitude are evaluated at
/// the given time; loads without one at `ramp` times their value.
VecX external_forces(const model::Model& model, const model::Step& step, Real step_time,
                     Real total_time, Real ramp);

/// The *CLOAD part of external_forces.
VecX concentrated_forces(const model::Model& model, const model::Step& step, Real step_time,
                         Real total_time, Real ramp);

/// The *DLOAD pressure part of external_forces on the faces at nodal positions `x`
/// (n_nodes x 3): the reference coordinates for small strain, the deformed ones for follower
/// pressure under NLGEOM.
VecX pressure_forces(const model::Model& model, const model::Step& step, Real step_time,
                     Real total_time, Real ramp, const MatX3& x);

/// The *DLOAD GRAV and CENTRIF part of external_forces with the nodes displaced by `u`
/// (3 * n_nodes): zero for small strain; under NLGEOM the centrifugal force follows the mass.
VecX body_forces(const model::Model& model, const model::Step& step, Real step_time,
                 Real total_time, Real ramp, const VecX& u);

/// A step's *DLOAD pressures and body loads on the reference configuration, summed per
/// amplitude (-1: ramped with the step) at unit load factor. Without NLGEOM they are linear in
/// their factors, so a step computes them once instead of at every Newton iteration.
struct DistributedLoadShapes {
  std::vector<int> amplitudes;
  std::vector<VecX> forces;  ///< 3 * n_nodes each
};
DistributedLoadShapes distributed_load_shapes(const model::Model& model, const model::Step& step);

/// pressure_forces + body_forces on the reference configuration, from the step's shapes.
VecX distributed_forces(const model::Model& model, const DistributedLoadShapes& shapes,
                        Real step_time, Real total_time, Real ramp);

/// The acceleration field of a body load scaled by its load factor at a time.
element::BodyAcceleration body_acceleration(const model::Model& model, const model::BodyLoad& load,
                                            Real step_time, Real total_time, Real ramp);

/// Values of the prescribed dofs at a time: amplitude-driven ones evaluated there, the others
/// `start + ramp * (value - start)` with start = `u_start` at that dof; FIXED ones hold
/// `u_previous` (the previous step's end).
VecX prescribed_values(const model::Model& model, const model::Step& step,
                       const assembly::DofMap& dofs, Real step_time, Real total_time, Real ramp,
                       const VecX& u_start, const VecX& u_previous);

/// Temperature change from the initial state at every node at the step end (zero if none).
VecX temperature_change(const model::Model& model, const model::Step& step);

/// The nodal temperatures (initial + dT) a frame reports; empty when the model defines no
/// temperatures at all (no initial conditions, no *TEMPERATURE in any step).
VecX nodal_temperatures(const model::Model& model, const VecX& dT);

/// A load on a node that no element or equation reaches would silently vanish: refuse it.
void require_loads_reach_elements(const model::Model& model, const assembly::DofMap& dofs,
                                  const VecX& f);

}  // namespace kontakt::analysis
