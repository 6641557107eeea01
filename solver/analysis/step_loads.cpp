#include "analysis/step_loads.hpp"

#include <algorithm>

#include "analysis/element_access.hpp"

namespace kontakt::analysis {

Real amplitude_factor(const model::Model& model, int amplitude, Real step_time, Real total_time) {
  if (amplitude < 0) return 1.0;
  const auto& amp = model.amplitudes[amplitude];
  return amp.value_at(amp.total_time ? total_time : step_time);
}

namespace {
Real load_factor(const model::Model& model, int amplitude, Real step_time, Real total_time,
                 Real ramp) {
  return amplitude < 0 ? ramp : amplitude_factor(model, amplitude, step_time, total_time);
}
}  // namespace

VecX concentrated_forces(const model::Model& model, const model::Step& step, Real step_time,
                         Real total_time, Real ramp) {
  VecX f = VecX::Zero(3 * model.n_nodes());
  for (const auto& load : step.cloads) {
    const Real value = load.value * load_factor(model, load.amplitude, step_time, total_time, ramp);
    const auto frame = model.local_frames.find(load.node);  // a local component (*TRANSFORM)
    if (frame == model.local_frames.end())
      f[3 * load.node + load.dof] += value;
    else
      f.segment<3>(3 * load.node) += value * frame->second.col(load.dof);
  }
  return f;
}

namespace {
/// Adds one face pressure's nodal forces at the value `p` on the nodal positions `x` to `f`.
void add_pressure(const model::Model& model, const model::PressureLoad& load, const MatX3& x, Real p,
                  VecX& f) {
  const auto& el = model.mesh.elements[load.face.element];
  MatX3 xe(el.nodes.size(), 3);
  for (std::size_t a = 0; a < el.nodes.size(); ++a) xe.row(a) = x.row(el.nodes[a]);
  VecX fe;
  naming_element(el, [&] { element::pressure_load(el.type, load.face.face, xe, p, fe); });
  for (std::size_t a = 0; a < el.nodes.size(); ++a)
    f.segment<3>(3 * el.nodes[a]) += fe.segment<3>(3 * static_cast<Index>(a));
}

/// Adds one body load's nodal forces under the acceleration `b` with the nodes displaced by `u`.
void add_body_load(const model::Model& model, const model::Step& step,
                   const model::BodyLoad& load, const element::BodyAcceleration& b, const VecX& u,
                   VecX& f) {
  for (int e : load.elements) {
    const auto& el = model.mesh.elements[static_cast<std::size_t>(e)];
    VecX fe;
    naming_element(el, [&] {
      element::body_load(el.type, element_coords(model, el), element_displacements(el, u),
                         element_material_def(model, el, &step).density.rows.front()[0], b, fe);
    });
    for (std::size_t a = 0; a < el.nodes.size(); ++a)
      f.segment<3>(3 * el.nodes[a]) += fe.segment<3>(3 * static_cast<Index>(a));
  }
}
}  // namespace

VecX pressure_forces(const model::Model& model, const model::Step& step, Real step_time,
                     Real total_time, Real ramp, const MatX3& x) {
  VecX f = VecX::Zero(3 * model.n_nodes());
  for (const auto& load : step.pressures)
    add_pressure(model, load, x,
                 load.value * load_factor(model, load.amplitude, step_time, total_time, ramp), f);
  return f;
}

element::BodyAcceleration body_acceleration(const model::Model& model, const model::BodyLoad& load,
                                            Real step_time, Real total_time, Real ramp) {
  const bool gravity = load.kind == model::BodyLoad::Kind::Gravity;
  return {.kind = gravity ? element::BodyAcceleration::Kind::Gravity
                          : element::BodyAcceleration::Kind::Centrifugal,
          .magnitude = load.value * load_factor(model, load.amplitude, step_time, total_time, ramp),
          .point = load.point,
          .direction = load.direction};
}

VecX body_forces(const model::Model& model, const model::Step& step, Real step_time,
                 Real total_time, Real ramp, const VecX& u) {
  VecX f = VecX::Zero(3 * model.n_nodes());
  for (const auto& load : step.body_loads)
    add_body_load(model, step, load, body_acceleration(model, load, step_time, total_time, ramp),
                  u, f);
  return f;
}

DistributedLoadShapes distributed_load_shapes(const model::Model& model, const model::Step& step) {
  DistributedLoadShapes shapes;
  const auto shape_of = [&](int amplitude) -> VecX& {
    const auto at = std::find(shapes.amplitudes.begin(), shapes.amplitudes.end(), amplitude);
    if (at != shapes.amplitudes.end()) return shapes.forces[at - shapes.amplitudes.begin()];
    shapes.amplitudes.push_back(amplitude);
    return shapes.forces.emplace_back(VecX::Zero(3 * model.n_nodes()));
  };
  for (const auto& load : step.pressures)
    add_pressure(model, load, model.mesh.coords, load.value, shape_of(load.amplitude));
  const VecX at_rest = VecX::Zero(3 * model.n_nodes());
  for (const auto& load : step.body_loads) {
    element::BodyAcceleration unit = body_acceleration(model, load, 0, 0, 1);
    unit.magnitude = load.value;
    add_body_load(model, step, load, unit, at_rest, shape_of(load.amplitude));
  }
  return shapes;
}

VecX distributed_forces(const model::Model& model, const DistributedLoadShapes& shapes,
                        Real step_time, Real total_time, Real ramp) {
  VecX f = VecX::Zero(3 * model.n_nodes());
  for (std::size_t k = 0; k < shapes.forces.size(); ++k)
    f += load_factor(model, shapes.amplitudes[k], step_time, total_time, ramp) * shapes.forces[k];
  return f;
}

VecX external_forces(const model::Model& model, const model::Step& step, Real step_time,
                     Real total_time, Real ramp) {
  return concentrated_forces(model, step, step_time, total_time, ramp) +
         pressure_forces(model, step, step_time, total_time, ramp, model.mesh.coords) +
         body_forces(model, step, step_time, total_time, ramp, VecX::Zero(3 * model.n_nodes()));
}

VecX prescribed_values(const model::Model& model, const model::Step& step,
                       const assembly::DofMap& dofs, Real step_time, Real total_time, Real ramp,
                       const VecX& u_start, const VecX& u_previous) {
  VecX g = VecX::Zero(dofs.n_prescribed());
  for (const auto& bc : step.boundaries) {  // later entries win, as in ccx
    const int d = 3 * bc.node + bc.dof;
    Real value;
    if (bc.hold_previous) {
      value = dofs.unknown_value(u_previous, d);
    } else if (bc.amplitude >= 0) {
      value = bc.value * amplitude_factor(model, bc.amplitude, step_time, total_time);
    } else {
      const Real start = dofs.unknown_value(u_start, d);
      value = start + ramp * (bc.value - start);
    }
    g[dofs.prescribed_slot(d)] = value;
  }
  return g;
}

VecX temperature_change(const model::Model& model, const model::Step& step) {
  const int n = model.n_nodes();
  if (step.temperatures.size() == 0) return VecX::Zero(n);
  VecX initial = model.initial_temperatures.size() ? model.initial_temperatures : VecX::Zero(n);
  return step.temperatures - initial;
}

VecX nodal_temperatures(const model::Model& model, const VecX& dT) {
  const bool any = model.initial_temperatures.size() > 0 ||
                   std::any_of(model.steps.begin(), model.steps.end(),
                               [](const model::Step& s) { return s.temperatures.size() > 0; });
  if (!any) return {};
  VecX t = model.initial_temperatures.size() ? model.initial_temperatures
                                             : VecX::Zero(model.n_nodes());
  if (dT.size() == t.size()) t += dT;
  return t;
}

void require_loads_reach_elements(const model::Model& model, const assembly::DofMap& dofs,
                                  const VecX& f) {
  // A dof with no terms is either off the elements (the error) or held at zero by a
  // constraint (a 2D element's out-of-plane dof, where a face load's round-off lands).
  std::vector<char> on_element(static_cast<std::size_t>(model.n_nodes()), 0);
  for (const auto& el : model.mesh.elements)
    for (int n : el.nodes) on_element[static_cast<std::size_t>(n)] = 1;
  for (int d = 0; d < dofs.n_dofs(); ++d)
    if (f[d] != 0 && dofs.terms_begin(d) == dofs.terms_end(d) &&
        !on_element[static_cast<std::size_t>(d / 3)])
      throw SolverError("a load acts on " + dofs.describe(model, d) +
                        ", which belongs to no element: the load would have no effect");
}

}  // namespace kontakt::analysis
