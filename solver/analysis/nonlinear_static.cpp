// Nonlinear static driver. For each step:
//   loads and prescribed values ramp from the previous step's end values to the step's own
//   (amplitudes, where given, drive them instead); IncrementControl proposes increments.
// For each increment:
//   contact (when the model has pairs) builds its points and pairings at the converged state
//   and fixes the contact groups of the sparsity pattern; the prescribed dofs jump to their new
//   values, the free ones start where the last increment ended; Newton iterations solve
//   K dx = T^T (f_ext - f_int - f_contact) until Convergence says so (with the contact rules
//   of the pairs' schemes; line search for the linear surface-to-surface variants).
//   A cutback restores the last converged state and retries smaller.
// On convergence the linear contact variants check that their frozen geometry has not drifted
// (else the increment is redone smaller), and the frame is handed to the writers.
#include "analysis/nonlinear_static.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "analysis/element_access.hpp"
#include "analysis/small_strain_frame.hpp"
#include "analysis/step_loads.hpp"
#include "analysis/constraint_layout.hpp"
#include "assembly/assembler.hpp"
#include "contact/contact_extrapolation.hpp"
#include "contact/contact_system.hpp"
#include "core/parallel.hpp"
#include "element/element_state.hpp"
#include "element/solid_plastic.hpp"
#include "element/total_lagrangian.hpp"
#include "element/total_lagrangian_plastic.hpp"
#include "linsolve/spd_solve.hpp"
#include "nonlinear/convergence.hpp"
#include "nonlinear/increment_control.hpp"
#include "nonlinear/static_predictor.hpp"

namespace kontakt::analysis {

namespace {

using Clock = std::chrono::steady_clock;

using PointStates = std::vector<element::ElementState>;  ///< per element

/// What an element reports at its points in the state last evaluated.
struct ElementOutput {
  MatX6 stress, strain;  ///< Cauchy stress and strain (Green-Lagrange under NLGEOM)
  VecX energy_density, peeq;
};

/// Internal forces, tangent and the average force measure q_bar at a displacement state.
struct Evaluation {
  assembly::ReducedSystem system;  ///< tangent and T^T (f_ext - f_int)
  VecX internal_force;             ///< full dof vector (reaction forces at constrained dofs)
  Real force_average = 0;          ///< q_bar: mean |element nodal force component|
  std::vector<ElementOutput> outputs;
  PointStates trial;               ///< plastic point states reached (plastic elements only)
};

material::HardeningTable hardening_of(const model::Model& model, const model::Element& el) {
  return {element_material_def(model, el).plastic};
}

/// One element's tangent, internal force and point output: total Lagrangian under NLGEOM
/// (finite-strain J2 for plastic materials), small-strain J2 return mapping for plastic
/// materials, linear elasticity otherwise (whose constant stiffness is skipped when `K` is null).
void element_response(const model::Model& model, const model::Element& el, bool nlgeom,
                      const VecX& u, const VecX& dT, const element::ElementState& committed,
                      MatX* K, VecX& f_int, ElementOutput& out, element::ElementState& trial) {
  const MatX3 X = element_coords(model, el), ue = element_displacements(el, u);
  const VecX dTe = element_values(el, dT);
  const auto mat = element_material(model, el);
  const bool plastic = !element_material_def(model, el).plastic.empty();
  if (nlgeom && plastic) {
    element::NlgeomPlasticResult r;
    element::nlgeom_plastic_element(el.type, X, mat, hardening_of(model, el), ue, dTe, committed,
                                    true, r);
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
    element::plastic_element(el.type, X, mat, hardening_of(model, el), ue, dTe, committed, true, r);
    *K = std::move(r.tangent);
    f_int = std::move(r.internal_force);
    trial = std::move(r.state);
    out = {std::move(r.stress), std::move(r.strain), std::move(r.energy_density), std::move(r.peeq)};
  } else {
    element::IpResults r;
    element::recover(el.type, X, mat, ue, dTe, r);
    if (K) element::linear_stiffness(el.type, X, mat, *K);
    f_int = std::move(r.internal_force);
    trial = committed;
    out = {std::move(r.stress), std::move(r.strain), std::move(r.energy_density), VecX()};
  }
  // The nonlinear tangents are unsymmetric by O(alpha dT) with a thermal strain (ccx's
  // mechanical deformation gradient) and very slightly where points yield; the Cholesky
  // solver takes their symmetric part, which costs a little convergence rate there.
  if (nlgeom || plastic) *K = 0.5 * (*K + K->transpose()).eval();
}

/// Contact's part of an evaluation: the system and how many times it was evaluated in the
/// current increment (its re-pairing rule counts evaluations).
struct ContactEvaluation {
  contact::ContactSystem* system = nullptr;
  int evaluations = 0;
};

/// The assembled stiffness of linear elements (small strain, elastic), which stays the same
/// through a step: assembled once per pattern generation and reused, so iterations (contact)
/// only recompute element forces.
struct LinearElementCache {
  bool usable = false;          ///< every element of the step is linear
  std::uint64_t generation = 0;  ///< pattern the values belong to (0: none yet)
  std::vector<Real> values;
};

/// Assembles the tangent and residual at `u` (full dof vector) with temperatures `dT`. A
/// nonzero `prescribed_step` (per prescribed slot) moves the constrained dofs within the
/// linearised system (-K g on the right-hand side), so the free dofs follow them at once.
Evaluation evaluate(const model::Model& model, const assembly::AssemblyPlan& plan, bool nlgeom,
                    const PointStates& committed, const VecX& u, const VecX& dT,
                    const VecX& f_ext, const VecX& prescribed_step, ContactEvaluation& contact,
                    LinearElementCache& cache, int threads) {
  const auto& elements = model.mesh.elements;
  Evaluation ev;
  std::vector<VecX> f_el(elements.size());
  ev.outputs.resize(elements.size());
  ev.trial.resize(elements.size());
  const bool reuse = cache.usable && cache.generation == plan.generation &&
                     (prescribed_step.size() == 0 || prescribed_step.isZero());
  if (reuse) {
    ev.system.values = cache.values;
    assembly::assemble_loads(
        model, plan,
        [&](int e, VecX& f) {
          const auto& el = elements[e];
          naming_element(el, [&] {
            element_response(model, el, nlgeom, u, dT, committed[e], nullptr, f_el[e],
                             ev.outputs[e], ev.trial[e]);
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
          naming_element(el, [&] {
            element_response(model, el, nlgeom, u, dT, committed[e], &K, f_el[e], ev.outputs[e],
                             ev.trial[e]);
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
  Real sum = 0;
  Index count = 0;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& nodes = elements[e].nodes;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (int c = 0; c < 3; ++c) ev.internal_force[3 * nodes[a] + c] += f_el[e][3 * a + c];
    sum += f_el[e].cwiseAbs().sum();
    count += f_el[e].size();
  }
  if (contact.system) {
    // Contact groups act like elements: scattered with the same dof reduction, part of the
    // reaction forces and of the average force (ccx counts its contact springs in q_bar).
    contact::ContactSystem& c = *contact.system;
    c.evaluate(u, ++contact.evaluations, threads);
    std::vector<const MatX*> K;
    std::vector<const VecX*> f;
    std::vector<VecX> minus_f(plan.groups.size());
    for (std::size_t g = 0; g < plan.groups.size(); ++g) {
      const auto& cg = c.contributions()[g];
      minus_f[g] = -cg.f_int;
      K.push_back(&cg.K);
      f.push_back(&minus_f[g]);
      const auto& nodes = plan.groups[g];
      for (std::size_t a = 0; a < nodes.size(); ++a)
        ev.internal_force.segment<3>(3 * nodes[a]) += cg.f_int.segment<3>(3 * a);
    }
    assembly::scatter_groups(plan, prescribed_step, K, f, ev.system);
    sum += c.force_abs_sum();
    count += c.force_components();
  }
  ev.force_average = count ? sum / static_cast<Real>(count) : 0;
  assembly::add_nodal_forces(*plan.dofs, f_ext, ev.system.rhs);
  return ev;
}

/// The output frame of a converged state from its last evaluation.
output::Frame converged_frame(const model::Model& model, const VecX& u, const Evaluation& ev) {
  output::Frame frame = sized_frame(model, u);
  frame.RF = Eigen::Map<const MatX3>(ev.internal_force.data(), model.n_nodes(), 3);
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
  return frame;
}

/// Element states at the start: plastic points virgin, C3D8I mode amplitudes zero.
PointStates initial_point_states(const model::Model& model) {
  PointStates states(model.mesh.elements.size());
  for (std::size_t e = 0; e < states.size(); ++e) {
    const auto& el = model.mesh.elements[e];
    if (!element_material_def(model, el).plastic.empty())
      states[e].points.resize(element::traits(el.type).n_ip);
    if (el.type == element::ElementType::C3D8I) states[e].modes = MatX3::Zero(3, 3);
  }
  return states;
}

nonlinear::StepTiming step_timing(const model::Step& step) {
  const auto& p = step.procedure;
  return {.period = p.period,
          .initial_increment = p.initial_increment,
          .min_increment = p.min_increment.value_or(0),
          .max_increment = p.max_increment.value_or(0),
          .direct = p.direct,
          .max_increments = step.max_increments};
}

Real max_abs(const VecX& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0; }

/// A linear contact variant whose frozen gaps differ from fresh projections by more than this
/// fraction of the largest overclosure redoes the increment smaller.
constexpr Real kDriftTolerance = 0.1;

/// How much smaller: the drift grows about with the square of the increment (the frozen normal
/// is off by the sliding, and so is the gap along it: measured 0.37 -> 0.11 for a halved
/// increment on the Hertz model), so one redo aims at 80 % of the tolerance.
Real drift_cutback_factor(Real drift) {
  return std::clamp(std::sqrt(0.8 * kDriftTolerance / drift), 0.25, 0.75);
}

/// The step's controls with ccx's face-to-face changes for the linear surface-to-surface
/// variants: the iteration cap is itf2f, the next increment is never shrunk for slow
/// convergence (thesis 4.4.2) and grows after increments of up to I_G + 12 iterations.
nonlinear::SolutionControls contact_controls(nonlinear::SolutionControls c,
                                             nonlinear::ContactCriteria criteria,
                                             const model::ContactControls& cc) {
  if (criteria != nonlinear::ContactCriteria::SurfaceToSurface) return c;
  c.max_iterations = cc.itf2f;
  c.slow_increment_iterations = std::numeric_limits<int>::max();
  c.fast_increment_iterations += 12;
  return c;
}


}  // namespace

bool needs_newton(const model::Model& model) {
  if (!model.contact_pairs.empty()) return true;
  for (const auto& step : model.steps)
    if (step.nlgeom) return true;
  for (const auto& el : model.mesh.elements)
    if (!element_material_def(model, el).plastic.empty()) return true;
  return false;
}

void run_nonlinear_static(const model::Model& model, const NonlinearOptions& options,
                          FrameSink& frames, EventSink& events) {
  if (model.steps.empty())
    throw InputError({model.source_file, 0}, "*STEP", "the deck defines no step");
  PointStates committed = initial_point_states(model);
  const int threads = resolve_threads(options.threads);
  const auto t0 = Clock::now();
  auto wall = [&] { return std::chrono::duration<Real>(Clock::now() - t0).count(); };

  const int n_dofs = 3 * model.n_nodes();
  VecX u = VecX::Zero(n_dofs);             // converged displacement
  VecX cloads_prev = VecX::Zero(n_dofs);   // concentrated loads at the previous step end
  VecX dT_prev = VecX::Zero(model.n_nodes());
  Real total_time_start = 0, last_q_bar = 0, max_mises = 0;
  Real max_contact_pressure = 0, total_contact_force = 0;
  int total_iterations = 0, drift_redos = 0;
  contact::ContactSystem contact(model);
  bool any_plastic = false;
  for (const auto& m : model.materials) any_plastic |= !m.plastic.empty();
  const nonlinear::ContactCriteria contact_rules = contact.criteria();
  ConstraintLayout layout;
  auto solver = linsolve::make_cholmod_solver();
  linsolve::SpdSolve spd(*solver, /*allow_indefinite=*/true);  // tangents past limit points

  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const model::Step& step = model.steps[s];
    const int step_no = static_cast<int>(s) + 1;
    events.on_event({.kind = Event::Kind::Step, .step = step_no, .wall_time = wall()});
    if (!step.procedure.data_line_given)
      events.on_event({.kind = Event::Kind::Warning, .step = step_no, .wall_time = wall(),
                       .message = step.where.file + ":" + std::to_string(step.where.line) +
                                  ": *STATIC has no data line: one increment of 1 over a step "
                                  "time of 1"});
    layout.update(model, step, *solver, threads);
    const assembly::DofMap& dofs = layout.dofs();
    const assembly::AssemblyPlan& plan = layout.plan();
    const Real period = step.procedure.period;
    const VecX u_step_start = u;
    const VecX dT_end = temperature_change(model, step);
    // Loads without amplitude ramp from the previous step's end values to this step's.
    // Pressures follow the deformed faces under NLGEOM (their load stiffness is left out of
    // the tangent, which keeps it symmetric at the price of slower convergence under
    // large pressure-driven rotations).
    const model::Step* previous = s > 0 ? &model.steps[s - 1] : nullptr;
    require_loads_reach_elements(
        model, dofs, external_forces(model, step, period, total_time_start + period, 1.0));
    auto loads_at = [&](Real t, const VecX& u_now) {
      const Real ramp = t / period;
      const MatX3 x = step.nlgeom ? MatX3(model.mesh.coords +
                                          Eigen::Map<const MatX3>(u_now.data(), model.n_nodes(), 3))
                                  : model.mesh.coords;
      VecX f = cloads_prev * (1 - ramp) +
               concentrated_forces(model, step, t, total_time_start + t, ramp) +
               pressure_forces(model, step, t, total_time_start + t, ramp, x);
      if (previous)  // the previous step's pressures fade out as this step's take over
        f += pressure_forces(model, *previous, previous->procedure.period, total_time_start,
                             1 - ramp, x);
      return f;
    };

    LinearElementCache element_cache;
    element_cache.usable = !step.nlgeom && !any_plastic;
    const nonlinear::SolutionControls controls = contact_controls(
        options.controls ? *options.controls : step.controls, contact_rules, step.contact_controls);
    nonlinear::Convergence convergence(controls, last_q_bar);
    convergence.set_contact_criteria(contact_rules, step.contact_controls.delcon);
    nonlinear::IncrementControl increments(step_timing(step), controls);
    // Line search (ccx: face-to-face contact only, from iteration 2, with contact active).
    const bool line_search = contact_rules == nonlinear::ContactCriteria::SurfaceToSurface;
    VecX x = VecX::Zero(dofs.n_equations());
    for (int eq = 0; eq < dofs.n_equations(); ++eq) x[eq] = u[dofs.equation_dof(eq)];
    nonlinear::StaticPredictor predictor;  // one per step: a step starts from its converged state

    while (!increments.finished()) {
      const Real t = increments.step_time() + increments.increment();
      const Real ramp = t / period;
      const VecX g = prescribed_values(model, step, dofs, t, total_time_start + t, ramp,
                                       u_step_start, u_step_start);

      const VecX dT = dT_prev * (1 - ramp) + dT_end * ramp;
      // Iteration 1 starts from the static predictor's extrapolation of the converged state
      // (the converged state itself in an increment that starts a step) and moves the
      // prescribed dofs to their new values through the linearised system; later iterations
      // correct the free dofs only.
      const Real t_old = increments.step_time();
      const VecX u_start = predictor.start(u, increments.increment());
      VecX x_trial(dofs.n_equations()), g_old(dofs.n_prescribed());
      for (int eq = 0; eq < dofs.n_equations(); ++eq) x_trial[eq] = u_start[dofs.equation_dof(eq)];
      for (int k = 0; k < dofs.n_prescribed(); ++k) g_old[k] = u_start[dofs.prescribed_dof(k)];
      VecX u_trial = dofs.expand(x_trial, g_old);
      const VecX no_step = VecX::Zero(dofs.n_prescribed());
      ContactEvaluation contact_eval{contact.empty() ? nullptr : &contact, 0};
      if (!contact.empty()) {
        contact.begin_increment(u,  // pairings at the converged state, not the prediction
                                {.step = step_no, .increment = increments.increment_number(),
                                 .fraction_start = t_old / period, .fraction_end = ramp},
                                threads);
        layout.set_contact_groups(contact.groups(), *solver, threads);
      }
      Evaluation ev;
      bool first_evaluated = false;
      for (int it = 1;; ++it) {
        if (options.cancel && options.cancel->load())
          throw Cancelled("cancelled in step " + std::to_string(step_no) + ", increment " +
                          std::to_string(increments.increment_number()));
        linsolve::SpdSolveReport report;
        nonlinear::Verdict verdict;
        try {
          if (it == 1) {
            ev = evaluate(model, plan, step.nlgeom, committed, u_trial, dT, loads_at(t, u_trial),
                          g - g_old, contact_eval, element_cache, threads);
            convergence.begin_increment(contact.empty() ? -1 : contact.n_active());
            first_evaluated = true;
          }
          spd.factorise(plan.pattern, ev.system.values, report);
          const VecX dx = spd.solve(plan.pattern, ev.system.values, ev.system.rhs, report);
          const VecX x_old = x_trial, rhs_old = ev.system.rhs;
          x_trial = x_old + dx;
          VecX u_new = dofs.expand(x_trial, g);
          ev = evaluate(model, plan, step.nlgeom, committed, u_new, dT, loads_at(t, u_new),
                        no_step, contact_eval, element_cache, threads);
          if (line_search && it > 1 && contact.n_active() > 0) {
            // The root of the residual's projection on dx, from its values at both ends.
            const Real r0 = dx.dot(rhs_old), r1 = dx.dot(ev.system.rhs);
            Real eta = r0 - r1 != 0 ? r0 / (r0 - r1) : 1;
            eta = std::clamp(eta, step.contact_controls.line_search_min,
                             step.contact_controls.line_search_max);
            if (std::abs(eta - 1) > 1e-3) {
              x_trial = x_old + eta * dx;
              u_new = dofs.expand(x_trial, g);
              ev = evaluate(model, plan, step.nlgeom, committed, u_new, dT, loads_at(t, u_new),
                            no_step, contact_eval, element_cache, threads);
            }
          }
          const Real c_max = max_abs(u_new - u_trial);
          u_trial = u_new;
          verdict = convergence.check(
              it, {ev.force_average, max_abs(ev.system.rhs), c_max,
                   contact.empty() ? -1 : contact.n_active()});
        } catch (const SolverError& e) {  // singular tangent, inverted element: cut back
          if (!first_evaluated) convergence.begin_increment();
          verdict.kind = nonlinear::Verdict::Kind::Cutback;
          verdict.cutback_factor = controls.divergence_cutback;
          verdict.reason = e.what();
        }
        ++total_iterations;
        events.on_event({.kind = Event::Kind::Iteration, .step = step_no,
                         .increment = increments.increment_number(),
                         .attempt = increments.attempt(), .iteration = it,
                         .step_time = t, .total_time = total_time_start + t,
                         .dt = increments.increment(),
                         .residual = 100 * verdict.residual_ratio,
                         .correction = 100 * verdict.correction_ratio,
                         .contact_elements = contact.empty() ? -1 : contact.n_active(),
                         .wall_time = wall()});
        if (verdict.kind == nonlinear::Verdict::Kind::Converged && !contact.empty() &&
            contact_rules == nonlinear::ContactCriteria::SurfaceToSurface) {
          // Beyond the thesis (section 7.1): frozen projections that no longer lie under their
          // points give wrong gaps; redo the increment smaller while the limits allow it.
          const Real drift = contact.frozen_drift(u_trial);
          const Real factor = drift_cutback_factor(drift);
          if (drift > kDriftTolerance && !step.procedure.direct &&
              factor * increments.increment() >= increments.min_increment() &&
              increments.attempt() <= controls.max_cutbacks) {
            ++drift_redos;
            verdict.kind = nonlinear::Verdict::Kind::Cutback;
            verdict.cutback_factor = factor;
            verdict.reason = "frozen contact geometry drifted: gaps off by " +
                             std::to_string(drift) + " of the largest overclosure";
          }
        }
        if (verdict.kind == nonlinear::Verdict::Kind::Converged) {
          convergence.commit_increment();
          predictor.converged(u, u_trial, increments.increment());
          x = x_trial;
          u = u_trial;
          const int increment_no = increments.increment_number();
          const int attempt = increments.attempt();
          const Real dt = increments.increment();
          increments.converged(it);
          output::Frame frame = converged_frame(model, u, ev);
          for (std::size_t e = 0; e < committed.size(); ++e)
            if (!committed[e].empty()) committed[e] = ev.trial[e];
          frame.step = step_no;
          frame.increment = increment_no;
          frame.step_time = t;
          frame.total_time = total_time_start + t;
          frame.is_step_end = increments.finished();
          if (!contact.empty()) {
            frame.contact_points = contact.records(u);
            frame.contact_nodal = contact::contact_nodal_values(model, frame.contact_points,
                                                                contact.nodes_outside_master(u));
            frame.n_active_contact = contact.n_active();
            max_contact_pressure = contact.max_pressure();
            total_contact_force = contact.total_normal_force();
          }
          for (Index k = 0; k < frame.S.rows(); ++k) {
            const auto sr = frame.S.row(k);
            const Real a = sr[0] - sr[1], b = sr[1] - sr[2], c = sr[2] - sr[0];
            max_mises = std::max(max_mises, std::sqrt(0.5 * (a * a + b * b + c * c) +
                                                      3 * sr.tail<3>().squaredNorm()));
          }
          events.on_event({.kind = Event::Kind::Increment, .step = step_no,
                           .increment = increment_no, .attempt = attempt, .iteration = it,
                           .step_time = t, .total_time = total_time_start + t, .dt = dt,
                           .contact_elements = contact.empty() ? -1 : contact.n_active(),
                           .wall_time = wall()});
          frames.on_frame(step, frame);
          break;
        }
        if (verdict.kind == nonlinear::Verdict::Kind::Cutback) {
          events.on_event({.kind = Event::Kind::Cutback, .step = step_no,
                           .increment = increments.increment_number(),
                           .attempt = increments.attempt(), .iteration = it,
                           .step_time = t_old, .total_time = total_time_start + t_old,
                           .dt = increments.increment(), .wall_time = wall(),
                           .message = verdict.reason});
          increments.cut_back(verdict.cutback_factor, verdict.reason);
          break;
        }
      }
    }
    cloads_prev = concentrated_forces(model, step, period, total_time_start + period, 1.0);
    dT_prev = dT_end;
    last_q_bar = convergence.last_force_average();
    total_time_start += period;
  }
  Event done{.kind = Event::Kind::Done, .wall_time = wall(), .status = "converged"};
  done.iterations = total_iterations;
  done.max_displacement = 0;
  for (int n = 0; n < model.n_nodes(); ++n)
    done.max_displacement = std::max(done.max_displacement, u.segment<3>(3 * n).norm());
  done.max_mises = max_mises;
  done.has_contact = !contact.empty();
  done.max_contact_pressure = max_contact_pressure;
  done.total_contact_force = total_contact_force;
  done.drift_redos = drift_redos;
  events.on_event(done);
}

}  // namespace kontakt::analysis
