#include "analysis/nonlinear_system.hpp"

#include <algorithm>

#include "analysis/connector.hpp"
#include "analysis/truss.hpp"
#include "analysis/element_access.hpp"
#include "analysis/small_strain_frame.hpp"
#include "element/solid_plastic.hpp"
#include "element/total_lagrangian.hpp"
#include "element/total_lagrangian_plastic.hpp"
#include "model/plane_expansion.hpp"

namespace kontakt::analysis {

namespace {

/// One element's tangent, internal force and point output: total Lagrangian under NLGEOM
/// (finite-strain J2 for plastic materials), small-strain J2 return mapping for plastic
/// materials, linear elasticity otherwise (whose constant stiffness is skipped when `K` is null).
void element_response(const model::Model& model, const model::Element& el, bool nlgeom,
                      const VecX& u, const VecX& dT, const element::ElementState& committed,
                      const MatX3& added_at, MatX* K, VecX& f_int, ElementOutput& out,
                      element::ElementState& trial) {
  // An element added back starts strain-free where it was added: its reference moves there.
  MatX3 X = element_coords(model, el), ue = element_displacements(el, u);
  if (added_at.size()) {
    X += added_at;
    ue -= added_at;
  }
  const VecX dTe = element_values(el, dT);
  const auto mat = element_material(model, el);
  const bool plastic = !element_material_def(model, el).plastic.empty();
  if (nlgeom && plastic) {
    element::NlgeomPlasticResult r;
    const model::Material& def = element_material_def(model, el);
    element::nlgeom_plastic_element(el.type, X, mat, element::PlasticHardening(def.plastic, def.hardening_rule, &def.cyclic),
                                    ue, dTe, committed, true, r);
    *K = std::move(r.tangent);
    f_int = std::move(r.internal_force);
    trial = std::move(r.state);
    out = {std::move(r.cauchy), std::move(r.green_lagrange), std::move(r.energy_density),
           std::move(r.peeq)};
  } else if (nlgeom) {
    element::NlgeomResult r;
    element::nlgeom_element(el.type, X, mat, ue, dTe, true, r, committed.modes);
    *K = std::move(r.tangent);
    f_int = std::move(r.internal_force);
    trial.modes = std::move(r.modes);
    out = {std::move(r.cauchy), std::move(r.green_lagrange), std::move(r.energy_density), VecX()};
  } else if (plastic) {
    element::PlasticResult r;
    element::plastic_element(el.type, X, mat, element_material_def(model, el).plastic, ue, dTe, committed, true, r);
    *K = std::move(r.tangent);
    f_int = std::move(r.internal_force);
    trial = std::move(r.state);
    out = {std::move(r.stress), std::move(r.strain), std::move(r.energy_density), std::move(r.peeq)};
  } else {
    element::IpResults r;
    element::recover(el.type, X, mat, ue, dTe, r);
    add_initial_stress(model, el, X, r.stress, r.internal_force);
    if (K) element::linear_stiffness(el.type, X, mat, dTe, *K);
    f_int = std::move(r.internal_force);
    trial = committed;
    out = {std::move(r.stress), std::move(r.strain), std::move(r.energy_density), VecX()};
  }
  // The nonlinear tangents are unsymmetric by O(alpha dT) with a thermal strain (ccx's
  // mechanical deformation gradient) and very slightly where points yield; the Cholesky
  // solver takes their symmetric part, which costs a little convergence rate there.
  if (nlgeom || plastic) *K = 0.5 * (*K + K->transpose()).eval();
}

/// The frame's truss rows (Frame::truss_S, ...), left empty without trusses.
void truss_points(const model::Model& model, const VecX& u, bool nlgeom, output::Frame& frame) {
  const auto& connectors = model.connectors;
  if (std::none_of(connectors.begin(), connectors.end(),
                   [](const auto& c) { return c.kind == model::Connector::Kind::Truss; }))
    return;
  const Index n = static_cast<Index>(connectors.size());
  frame.truss_S = MatX6::Zero(n, 6);
  frame.truss_E = MatX6::Zero(n, 6);
  frame.truss_ENER = VecX::Zero(n);
  for (Index k = 0; k < n; ++k) {
    const model::Connector& c = connectors[static_cast<std::size_t>(k)];
    if (c.kind != model::Connector::Kind::Truss) continue;
    const auto& [a, b] = c.nodes;
    const TrussPointOutput p =
        truss_point_output(c, model.mesh.coords.row(a).transpose(),
                           model.mesh.coords.row(b).transpose(), u.segment<3>(3 * a),
                           u.segment<3>(3 * b), nlgeom);
    frame.truss_S.row(k) = p.stress.transpose();
    frame.truss_E.row(k) = p.strain.transpose();
    frame.truss_ENER[k] = p.energy_density;
  }
}

}  // namespace

ElementStates::ElementStates(const model::Model& model) {
  committed.resize(model.mesh.elements.size());
  for (std::size_t e = 0; e < committed.size(); ++e) {
    const auto& el = model.mesh.elements[e];
    if (!element_material_def(model, el).plastic.empty())
      committed[e].points.resize(element::traits(el.type).n_ip);
    if (el.type == element::ElementType::C3D8I) committed[e].modes = MatX3::Zero(3, 3);
  }
  trial = committed;
}

void ElementStates::commit() {
  for (std::size_t e = 0; e < committed.size(); ++e)
    if (!committed[e].empty()) committed[e] = trial[e];
}

Evaluation evaluate_elements(const model::Model& model, const assembly::AssemblyPlan& plan,
                             bool nlgeom, ElementStates& states, const VecX& u, const VecX& dT,
                             const VecX& prescribed_step, LinearElementCache& cache, int threads) {
  const auto& elements = model.mesh.elements;
  const auto& committed = states.committed;
  auto& trial = states.trial;
  Evaluation ev;
  std::vector<VecX> f_el(elements.size());
  ev.outputs.resize(elements.size());
  const MatX3 none;
  const auto is_active = [&](int e) {
    return states.active.empty() || states.active[static_cast<std::size_t>(e)];
  };
  const auto added_at = [&](int e) -> const MatX3& {
    return states.added_at.empty() ? none : states.added_at[static_cast<std::size_t>(e)];
  };
  // A removed element: no stiffness, no force, zero point values.
  const auto removed = [&](const model::Element& el, MatX* K, VecX& f_int, ElementOutput& out,
                           VecX& f) {
    const int n = 3 * static_cast<int>(el.nodes.size());
    const Index nip = element::traits(el.type).n_ip;
    if (K) K->setZero(n, n);
    f_int = VecX::Zero(n);
    f = f_int;
    out = {MatX6::Zero(nip, 6), MatX6::Zero(nip, 6), VecX::Zero(nip), VecX()};
  };
  const bool reuse = cache.usable && cache.generation == plan.generation &&
                     (prescribed_step.size() == 0 || prescribed_step.isZero());
  if (reuse) {
    ev.system.values = cache.values;
    assembly::assemble_loads(
        model, plan,
        [&](int e, VecX& f) {
          const auto& el = elements[e];
          if (!is_active(e)) return removed(el, nullptr, f_el[e], ev.outputs[e], f);
          naming_element(el, [&] {
            element_response(model, el, nlgeom, u, dT, committed[e], added_at(e), nullptr,
                             f_el[e], ev.outputs[e], trial[e]);
          });
          f = -f_el[e];
        },
        threads, ev.system.rhs);
  } else {
    // The assembler scatters K and -f_int (as the element "load").
    assembly::assemble(
        model, plan, prescribed_step,
        [&](int e, MatX& K, VecX& f) {
          const auto& el = elements[e];
          if (!is_active(e)) return removed(el, &K, f_el[e], ev.outputs[e], f);
          naming_element(el, [&] {
            element_response(model, el, nlgeom, u, dT, committed[e], added_at(e), &K, f_el[e],
                             ev.outputs[e], trial[e]);
          });
          f = -f_el[e];
        },
        threads, ev.system);
    if (cache.usable) {
      cache.values = ev.system.values;
      cache.generation = plan.generation;
    }
  }
  ev.internal_force = VecX::Zero(u.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& nodes = elements[e].nodes;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (int c = 0; c < 3; ++c) ev.internal_force[3 * nodes[a] + c] += f_el[e][3 * a + c];
    ev.force_abs_sum += f_el[e].cwiseAbs().sum();
    ev.force_components += f_el[e].size();
  }
  for (const model::Connector& c : model.connectors) {  // springs and gaps, serially: few
    const auto& [a, b] = c.nodes;
    const ConnectorResponse r =
        connector_response(c, model.mesh.coords.row(a).transpose(),
                           model.mesh.coords.row(b).transpose(), u.segment<3>(3 * a),
                           u.segment<3>(3 * b), nlgeom);
    assembly::scatter_nodes(plan, {a, b}, prescribed_step, r.stiffness, -r.force, ev.system);
    ev.internal_force.segment<3>(3 * a) += r.force.head<3>();
    ev.internal_force.segment<3>(3 * b) += r.force.tail<3>();
    ev.force_abs_sum += r.force.cwiseAbs().sum();
    ev.force_components += 6;
    ev.connector_energy += r.energy;
  }
  return ev;
}

/// The output frame of a converged state from its last evaluation.
output::Frame converged_frame(const model::Model& model, const VecX& u, const Evaluation& ev,
                              bool nlgeom) {
  output::Frame frame = sized_frame(model, u);
  frame.RF = Eigen::Map<const MatX3>(ev.internal_force.data(), model.n_nodes(), 3);
  model::fold_to_planar_nodes(model.planar_folds, frame.U, frame.RF);
  bool any_plastic = false;
  for (const auto& o : ev.outputs) any_plastic |= o.peeq.size() > 0;
  if (any_plastic) frame.PEEQ = VecX::Zero(frame.ip_offset.back());
  for (int e = 0; e < model.n_elements(); ++e) {
    const auto& el = model.mesh.elements[e];
    const auto& o = ev.outputs[e];
    const Index first = frame.ip_offset[e], n = frame.ip_offset[e + 1] - first;
    frame.S.middleRows(first, n) = o.stress;
    frame.E.middleRows(first, n) = o.strain;
    frame.ENER.segment(first, n) = o.energy_density;
    if (o.peeq.size()) frame.PEEQ.segment(first, n) = o.peeq;
    frame.ip_volume.segment(first, n) = element::ip_volumes(el.type, element_coords(model, el));
    frame.EVOL[e] = frame.ip_volume.segment(first, n).sum();
  }
  average_to_nodes(model, frame);
  truss_points(model, u, nlgeom, frame);
  return frame;
}

}  // namespace kontakt::analysis
