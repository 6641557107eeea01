// Nonlinear static driver: steps -> increments -> Newton iterations.
//
// A step ramps its loads and prescribed values from the previous step's end values to its own
// (amplitudes, where given, drive them instead) and lets IncrementControl propose increments.
// An increment starts from the converged state extrapolated by the static predictor; contact
// builds its points and pairings at the converged state (the linear variants freeze theirs at
// the prediction) and fixes its groups in the sparsity pattern. Each
// Newton iteration then
//   solves K dx = T^T (f_ext - f_int - f_contact) (iteration 1 also moves the prescribed dofs
//   to their new values through the linearised system), updates the displacements, evaluates
//   elements and contact at the new state (with a line search where contact asks for one),
//   and asks Convergence for a verdict.
// A converged increment that contact accepts is committed (element and contact point states,
// displacements) and handed to the writers; a cutback rolls the trial states back and retries
// the increment smaller.
#include "analysis/nonlinear_static.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "analysis/constraint_layout.hpp"
#include "analysis/distance_links.hpp"
#include "analysis/element_access.hpp"
#include "analysis/nonlinear_system.hpp"
#include "analysis/singular_system.hpp"
#include "analysis/step_loads.hpp"
#include "analysis/support_check.hpp"
#include "contact/contact_system.hpp"
#include "contact/stabilisation_schedule.hpp"
#include "core/parallel.hpp"
#include "linsolve/spd_solve.hpp"
#include "material/von_mises.hpp"
#include "nonlinear/convergence.hpp"
#include "nonlinear/increment_control.hpp"
#include "nonlinear/pseudo_transient.hpp"
#include "nonlinear/static_predictor.hpp"

namespace kontakt::analysis {

namespace {

using Clock = std::chrono::steady_clock;

/// `total_start`: the total time at the step's start (*TIME POINTS on total time).
nonlinear::StepTiming step_timing(const model::Model& model, const model::Step& step,
                                  Real total_start) {
  const auto& p = step.procedure;
  nonlinear::StepTiming timing{.period = p.period,
                               .initial_increment = p.initial_increment,
                               .min_increment = p.min_increment.value_or(0),
                               .max_increment = p.max_increment.value_or(0),
                               .direct = p.direct,
                               .max_increments = step.max_increments,
                               .time_points = {}};
  if (step.time_points >= 0) {
    const model::TimePoints& points = model.time_points[static_cast<std::size_t>(step.time_points)];
    for (const Real t : points.times)
      timing.time_points.push_back(points.total_time ? t - total_start : t);
  }
  return timing;
}

Real max_abs(const VecX& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0; }

/// The run: what lives across steps, and the phases of a step, an increment and an iteration.
class NonlinearStatic {
 public:
  NonlinearStatic(const model::Model& model, const NonlinearOptions& options, FrameSink& frames,
                  EventSink& events)
      : model_(model), options_(options), frames_(frames), events_(events),
        threads_(resolve_threads(options.threads)), t0_(Clock::now()),
        u_(VecX::Zero(3 * model.n_nodes())), cloads_prev_(VecX::Zero(3 * model.n_nodes())),
        dT_prev_(VecX::Zero(model.n_nodes())), elements_(model), contact_(model), links_(model),
        solver_(linsolve::make_cholmod_solver()),
        spd_(*solver_, /*allow_indefinite=*/true) {  // tangents past limit points
    for (const auto& m : model.materials) any_plastic_ |= !m.plastic.empty();
  }

  void run() {
    for (std::size_t s = 0; s < model_.steps.size(); ++s) run_step(static_cast<int>(s));
    report_done();
  }

 private:
  /// What stays fixed through one step.
  struct StepContext {
    const model::Step* step = nullptr;
    const model::Step* previous = nullptr;
    int number = 1;
    Real period = 1;
    VecX u_start, dT_end;
    model::SolutionControls controls;
    /// Without NLGEOM: the distributed loads of the step and of the previous one (fading out).
    std::optional<DistributedLoadShapes> loads, previous_loads;
  };
  /// One attempt at an increment: its times, targets and the Newton iterate.
  struct Attempt {
    Real t_old = 0, t = 0, ramp = 0;  ///< step times at its start and end, t / period
    VecX g, g_old;                    ///< prescribed values at its end and where it starts
    VecX dT;
    VecX x, u;                        ///< free unknowns and full displacements of the iterate
    Evaluation ev;                    ///< at the iterate
  };

  Real wall() const { return std::chrono::duration<Real>(Clock::now() - t0_).count(); }

  /// Runs `fn`, adding its wall time to `total`.
  template <class Fn>
  static auto timed(Real& total, Fn&& fn) {
    const auto start = Clock::now();
    struct Add {
      Real& total;
      Clock::time_point start;
      ~Add() { total += std::chrono::duration<Real>(Clock::now() - start).count(); }
    } add{total, start};
    return fn();
  }

  void run_step(int s) {
    const model::Step& step = model_.steps[s];
    StepContext sc{.step = &step, .previous = s > 0 ? &model_.steps[s - 1] : nullptr,
                   .number = s + 1, .period = step.procedure.period, .u_start = u_,
                   .dT_end = temperature_change(model_, step), .controls = {}, .loads = {}, .previous_loads = {}};
    if (!step.nlgeom) {
      sc.loads = distributed_load_shapes(model_, step);
      if (sc.previous) sc.previous_loads = distributed_load_shapes(model_, *sc.previous);
    }
    events_.on_event({.kind = Event::Kind::Step, .step = sc.number, .wall_time = wall()});
    if (!step.procedure.data_line_given)
      warn(sc.number, step.where.file + ":" + std::to_string(step.where.line) +
                          ": *STATIC has no data line: one increment of 1 over a step time of 1");
    layout_.update(model_, step, *solver_, threads_, links_.in_force());
    change_elements(step);
    contact_.begin_step(step);
    require_loads_reach_elements(
        model_, layout_.dofs(),
        external_forces(model_, step, sc.period, total_time_start_ + sc.period, 1.0));

    // A linear element's stiffness is constant unless its constants follow the temperature.
    element_cache_ = {.usable = !step.nlgeom && !any_plastic_ && !any_temperature_dependent_stiffness(model_),
                      .generation = 0, .values = {}};
    sc.controls = contact_.solution_controls(
        options_.controls ? *options_.controls : step.controls, step.contact_controls);
    convergence_.emplace(sc.controls, last_q_bar_);
    convergence_->set_contact_criteria(contact_.criteria(), step.contact_controls.delcon);
    increments_.emplace(step_timing(model_, step, total_time_start_), sc.controls);
    step_stabilisation_energy_ = 0;
    predictor_ = {};  // a step starts from its converged state

    while (!increments_->finished()) try_increment(sc);

    cloads_prev_ = concentrated_forces(model_, step, sc.period, total_time_start_ + sc.period, 1.0);
    dT_prev_ = sc.dT_end;
    last_q_bar_ = convergence_->last_force_average();
    total_time_start_ += sc.period;
  }

  /// *MODEL CHANGE, TYPE=ELEMENT: the step's active elements; one added back in this step is
  /// strain-free in the converged configuration it returns in.
  void change_elements(const model::Step& step) {
    const std::vector<char>& before = elements_.active;
    const auto active = [](const std::vector<char>& flags, std::size_t e) {
      return flags.empty() || flags[e];
    };
    if (before.empty() && step.element_active.empty()) return;
    elements_.added_at.resize(model_.mesh.elements.size());
    for (std::size_t e = 0; e < model_.mesh.elements.size(); ++e)
      if (active(step.element_active, e) && !active(before, e))
        elements_.added_at[e] = element_displacements(model_.mesh.elements[e], u_);
    elements_.active = step.element_active;
  }

  /// External forces at step time t on the configuration u: loads without amplitude ramp from
  /// the previous step's end values to this step's; under NLGEOM pressures follow the deformed
  /// faces and centrifugal forces the moving mass (their load stiffness is left out of the
  /// tangent, which keeps it symmetric at the price of slower convergence under large
  /// pressure-driven rotations; a spinning disk converged in ccx's iterations without it).
  VecX loads_at(const StepContext& sc, Real t, const VecX& u) const {
    const model::Step& step = *sc.step;
    const Real ramp = t / sc.period, total = total_time_start_ + t;
    VecX f = cloads_prev_ * (1 - ramp) + concentrated_forces(model_, step, t, total, ramp);
    // the previous step's distributed loads fade out from their end values (amplitudes
    // evaluated there, as ccx freezes them) as this step's take over
    const model::Step* previous = sc.previous;
    const Real previous_end = previous ? previous->procedure.period : 0;
    if (sc.loads) {
      f += distributed_forces(model_, *sc.loads, t, total, ramp);
      if (previous)
        f += (1 - ramp) * distributed_forces(model_, *sc.previous_loads, previous_end,
                                             total_time_start_, 1);
      return f;
    }
    const MatX3 x = model_.mesh.coords + Eigen::Map<const MatX3>(u.data(), model_.n_nodes(), 3);
    f += pressure_forces(model_, step, t, total, ramp, x) +
         body_forces(model_, step, t, total, ramp, u);  // the mass moves with NLGEOM
    if (previous)
      f += (1 - ramp) * (pressure_forces(model_, *previous, previous_end, total_time_start_, 1, x) +
                         body_forces(model_, *previous, previous_end, total_time_start_, 1, u));
    return f;
  }

  /// Elements, contact and loads at displacements `u`.
  Evaluation evaluate(const StepContext& sc, const Attempt& a, const VecX& u,
                      const VecX& prescribed_step) {
    const assembly::AssemblyPlan& plan = layout_.plan();
    Evaluation ev = timed(times_.elements, [&] {
      return evaluate_elements(model_, plan, sc.step->nlgeom, elements_, u, a.dT,
                               prescribed_step, element_cache_, threads_);
    });
    if (!contact_.empty()) {
      timed(times_.contact, [&] { contact_.update(u, threads_); });
      const contact::ForceMeasure f =
          contact_.add_to(plan, prescribed_step, ev.system, ev.internal_force);
      ev.force_abs_sum += f.abs_sum;
      ev.force_components += f.components;
    }
    assembly::add_nodal_forces(*plan.dofs, loads_at(sc, a.t, u), ev.system.rhs);
    return ev;
  }

  /// An attempt at the increment IncrementControl proposes, at its start: iteration 1 starts
  /// from the static predictor's extrapolation of the converged state and moves the prescribed
  /// dofs to their new values through the linearised system.
  Attempt begin_attempt(const StepContext& sc) {
    if (const std::vector<std::string> changes = links_.begin_increment(); !changes.empty()) {
      for (const std::string& change : changes) warn(sc.number, change);
      layout_.update(model_, *sc.step, *solver_, threads_, links_.in_force());
      predictor_ = {};  // nor is the path before it extrapolated across the change (ccx)
    }
    const assembly::DofMap& dofs = layout_.dofs();
    Attempt a;
    a.t_old = increments_->step_time();
    a.t = a.t_old + increments_->increment();
    a.ramp = a.t / sc.period;
    a.g = prescribed_values(model_, *sc.step, dofs, a.t, total_time_start_ + a.t, a.ramp,
                            sc.u_start, sc.u_start);
    a.dT = dT_prev_ * (1 - a.ramp) + sc.dT_end * a.ramp;
    const VecX u_predicted = predictor_.start(u_, increments_->increment());
    a.x.resize(dofs.n_equations());
    a.g_old.resize(dofs.n_prescribed());
    for (int eq = 0; eq < dofs.n_equations(); ++eq)
      a.x[eq] = dofs.unknown_value(u_predicted, dofs.equation_dof(eq));
    for (int k = 0; k < dofs.n_prescribed(); ++k)
      a.g_old[k] = dofs.unknown_value(u_predicted, dofs.prescribed_dof(k));
    a.u = dofs.expand(a.x, a.g_old);
    if (sc.step->nlgeom) layout_.relinearise(a.u);
    if (!contact_.empty()) {
      timed(times_.contact_search, [&] {
        contact_.begin_increment(u_,
                                 {.step = sc.number, .increment = increments_->increment_number(),
                                  .fraction_start = a.t_old / sc.period, .fraction_end = a.ramp},
                                 threads_, &u_predicted);
      });
      timed(times_.pattern, [&] { layout_.set_contact_groups(contact_.groups(), *solver_, threads_); });
    }
    return a;
  }

  /// Tries the increment IncrementControl proposes: converges and commits it, or cuts back.
  /// With contact stabilisation engaged (StabilisationSchedule), the attempt runs through the
  /// schedule's levels, each a Newton solve of its own, and ends with the springs released.
  void try_increment(const StepContext& sc) {
    Attempt a = begin_attempt(sc);
    const VecX x_start = a.x, u_start = a.u;
    VecX x_saved, u_saved;  // the last converged stabilised level
    Real saved_share = 0;   // ... and the share of the normal force its springs carried
    std::string engaged_because, release_failure;
    const auto mode = options_.contact_stabilisation;
    if (!contact_.empty() && (mode == ContactStabilisation::Always ||
                              (mode == ContactStabilisation::Auto && retry_stabilised_)))
      stabilisation_.engage();
    else
      stabilisation_.disengage();
    contact_.set_stabilisation(stabilisation_.factor());
    pseudo_.stop();
    bool at_start = true;   // the iterate sits where the attempt started
    int level_it = 0;       // iterations of the current level (of the attempt, unstabilised)
    int refreezes = 0;      // of the attempt's drifted contact geometry
    int level_pairings = 0; // of the current stabilised level
    bool pseudo_tried = false;  // the attempt ran its pseudo-transient continuation
    // Springs from the start of the attempt, for a reason the warning names.
    const auto engage_from_start = [&](const std::string& why) {
      warn(sc.number, "increment " + std::to_string(increments_->increment_number()) + ": " +
                          why + "; contact stabilisation engaged");
      stabilisation_.engage();
      contact_.set_stabilisation(stabilisation_.factor());
      a.x = x_start;
      a.u = u_start;
      if (sc.step->nlgeom) layout_.relinearise(a.u);  // T at the restored iterate
      at_start = true;
      level_it = 0;
    };
    // Back to the last converged stabilised level, for a new solve from there.
    const auto restore_saved_level = [&] {
      a.x = x_saved;
      a.u = u_saved;
      if (sc.step->nlgeom) layout_.relinearise(a.u);  // T at the restored iterate
      level_it = 0;
      level_pairings = 0;
    };
    // Where the springs find no way off: pseudo-transient continuation from the last level
    // they held (once an attempt), which lets a point contact fall onto what holds it.
    const auto damp_from_saved_level = [&](const std::string& why) {
      if (pseudo_tried || x_saved.size() == 0) return false;
      pseudo_tried = true;
      warn(sc.number, "increment " + std::to_string(increments_->increment_number()) + ": " + why +
                          "; pseudo-transient continuation from the last stabilised level");
      pseudo_.start(stabilisation_.absorbed_energy());  // what the saved level's springs held
      stabilisation_.disengage();
      contact_.set_stabilisation(0);
      contact_.pair_again();
      restore_saved_level();
      return true;
    };
    for (int it = 1;; ++it) {
      if (options_.cancel && options_.cancel->load())
        throw Cancelled("cancelled in step " + std::to_string(sc.number) + ", increment " +
                        std::to_string(increments_->increment_number()));
      nonlinear::Verdict verdict;
      bool singular = false, threw = false;
      try {
        if (level_it == 0) {
          a.ev = evaluate(sc, a, a.u,
                          at_start ? VecX(a.g - a.g_old) : VecX::Zero(a.g.size()));
          convergence_->begin_increment(contact_count());
          at_start = false;
        }
        verdict = iterate(sc, a, ++level_it);
      } catch (const linsolve::SingularMatrix& e) {
        if (level_it == 0) convergence_->begin_increment();
        verdict = failure(sc, singular_system_error(model_, layout_.dofs(), e).what());
        singular = threw = true;
      } catch (const SolverError& e) {  // inverted element, non-finite contact: cut back
        if (level_it == 0) convergence_->begin_increment();
        verdict = failure(sc, e.what());
        threw = true;
      }
      ++total_iterations_;
      report_iteration(sc, a, it, verdict);

      if (singular && !contact_.empty() && !stabilisation_.engaged() && !pseudo_.active() &&
          options_.contact_stabilisation != ContactStabilisation::Never) {
        // A body that only contact holds does not touch (yet): hold it with springs instead,
        // from the start of the attempt.
        const std::string held = bodies_held_only_by_contact(model_, layout_.dofs());
        if (!held.empty()) verdict.reason += "; " + held;
        engaged_because = verdict.reason;
        engage_from_start(verdict.reason);
        continue;
      }
      using Next = contact::StabilisationSchedule::Next;
      if (verdict.kind == nonlinear::Verdict::Kind::Converged && stabilisation_.engaged() &&
          !stabilisation_.releasing()) {
        // A stabilised level converged: step down, release the springs, or accept springs
        // that carry a negligible share of the load.
        if (contact_.separating())
          throw NonConvergence(
              "step " + std::to_string(sc.number) + ", increment " +
              std::to_string(increments_->increment_number()) +
              ": the loads move a body that only contact holds away from its contact (" +
              (engaged_because.empty() ? "no contact point touches" : engaged_because) +
              "): it has no equilibrium");
        if (level_pairings < kMaxRefreezes && contact_.unheld_penetration(a.u).depth > 0) {
          // Points passed through faces they were offered: this level goes on, paired again.
          contact_.pair_again();
          ++level_pairings;
          level_it = 0;
          continue;
        }
        level_pairings = 0;
        x_saved = a.x;
        u_saved = a.u;
        saved_share = contact_.stabilisation_share();
        const Next next = stabilisation_.converged(contact_.stabilisation_energy(),
                                                   contact_.stabilisation_share(),
                                                   contact_.approach_ratio());
        if (next == Next::Continue) {
          contact_.set_stabilisation(stabilisation_.factor());
          level_it = 0;
          continue;
        }
        if (next == Next::GiveUp) {
          stabilisation_diagnosis_ = no_release(stabilisation_.factor(), saved_share);
          verdict = failure(sc, release_failure.empty()
                                    ? stabilisation_diagnosis_
                                    : "releasing the springs failed: " + release_failure);
          if (damp_from_saved_level(verdict.reason)) continue;
        }
      }
      if (verdict.kind == nonlinear::Verdict::Kind::Converged) {
        verdict = judged_by_contact(sc, a, refreezes);
        if (verdict.kind == nonlinear::Verdict::Kind::Converged) {
          retry_stabilised_ = false;
          stabilisation_diagnosis_.clear();
          return commit_increment(sc, a, it);
        }
        if (verdict.kind == nonlinear::Verdict::Kind::Iterate) {  // a new Newton solve from here
          level_it = 0;
          continue;
        }
        return cut_back(sc, a, it, verdict);
      }
      if (verdict.kind != nonlinear::Verdict::Kind::Cutback) continue;
      if (pseudo_.active()) {
        // The damped motion may pass through worse residuals on its way (a snap): only its
        // step budget, a stall of its smallest residual, or a state it cannot evaluate ends it.
        if (!threw && !pseudo_.exhausted()) continue;
        verdict.reason = "pseudo-transient continuation failed after " +
                         std::to_string(pseudo_.steps()) + " steps: " + verdict.reason;
      } else if (stabilisation_.engaged()) {
        const bool release = stabilisation_.releasing();
        if (release) release_failure = verdict.reason;
        const Real held = stabilisation_.held_factor();
        const Next next = stabilisation_.failed();
        if (next == Next::GiveUp && held > 0) {
          stabilisation_diagnosis_ = no_release(held, saved_share);
          if (damp_from_saved_level(verdict.reason + "; " + stabilisation_diagnosis_)) continue;
        }
        if (next == Next::RestoreAndContinue) {
          warn(sc.number, "increment " + std::to_string(increments_->increment_number()) +
                              (release ? ": releasing the contact stabilisation failed ("
                                       : ": a contact stabilisation level failed (") +
                              verdict.reason + "); back to the last converged level, with springs of " +
                              std::to_string(stabilisation_.factor()) + " times the penalty");
          restore_saved_level();
          contact_.set_stabilisation(stabilisation_.factor());
          continue;
        }
      }
      if (!stabilisation_.engaged() && !pseudo_tried && !contact_.empty() &&
          options_.contact_stabilisation == ContactStabilisation::Auto) {
        // Before cutting back, the same increment with springs where a body only contact
        // holds: a point contact that rocks past a limit of its equilibrium (a coarse
        // punch's apex node, tilting) needs the whole increment to reach the nodes that hold
        // it, and a smaller one only crawls towards that limit.
        const std::string held = bodies_held_only_by_contact(model_, layout_.dofs());
        if (!held.empty()) {
          engaged_because = held;
          engage_from_start(verdict.reason + "; " + held);
          continue;
        }
      }
      // The retry of a failed attempt with contact starts stabilised: a contact set that
      // chatters (point contact, coarse meshes) settles while the springs hold the bodies.
      retry_stabilised_ = !contact_.empty();
      // What an attempt of this increment found out about the stabilisation stays in the
      // reasons of the later ones: the last is what the step's failure reports.
      if (!stabilisation_diagnosis_.empty()) verdict.reason += "; " + stabilisation_diagnosis_;
      return cut_back(sc, a, it, verdict);
    }
  }

  /// Why an attempt ended on stabilisation springs it could not release.
  static std::string no_release(Real factor, Real share) {
    std::ostringstream why;
    why << "the contact stabilisation found no way off its springs (the weakest level that "
           "converged, "
        << factor << " times the penalty, left them " << share
        << " of the normal force): contact on too few points can leave a body free to rock; "
           "refine the contact surfaces or use a surface-to-surface scheme";
    return why.str();
  }

  /// The verdict for an iteration that could not be completed.
  static nonlinear::Verdict failure(const StepContext& sc, std::string reason) {
    nonlinear::Verdict v;
    v.kind = nonlinear::Verdict::Kind::Cutback;
    v.cutback_factor = sc.controls.divergence_cutback;
    v.reason = std::move(reason);
    return v;
  }

  /// One Newton iteration from the iterate in `a`: solve, update, evaluate, judge.
  nonlinear::Verdict iterate(const StepContext& sc, Attempt& a, int it) {
    const assembly::DofMap& dofs = layout_.dofs();
    const assembly::AssemblyPlan& plan = layout_.plan();
    linsolve::SpdSolveReport report;
    // The skew part (friction slip) is empty while the tangent is symmetric.
    const auto& sys = a.ev.system;
    // Pseudo-transient continuation damps every dof by its shift times its own stiffness, and
    // shifts more while that is not enough to make the tangent positive definite.
    std::vector<Real> damped;
    VecX damping = VecX::Zero(pseudo_.active() ? plan.pattern.n : 0);
    const std::vector<Real>* tangent = &sys.values;
    for (;;) {
      if (pseudo_.active() && pseudo_.shift() > 0) {
        damped = sys.values;
        for (int j = 0; j < plan.pattern.n; ++j) {
          const Index d = plan.pattern.find(j, j);
          damping[j] = pseudo_.shift() * std::abs(sys.values[d]);
          damped[d] += damping[j];
        }
        tangent = &damped;
      }
      report = {};
      timed(times_.factorisation,
            [&] { spd_.factorise(plan.pattern, *tangent, report, sys.skew); });
      if (!pseudo_.active() || !report.indefinite || !pseudo_.raise()) break;
    }
    VecX dx = timed(times_.solve, [&] {
      return spd_.solve(plan.pattern, *tangent, sys.rhs, report, sys.skew);
    });
    if (report.stabilised && !warned_zero_energy_mode_) {
      warned_zero_energy_mode_ = true;
      const std::string held =
          contact_.n_active() == 0 ? bodies_held_only_by_contact(model_, dofs) : "";
      warn(sc.number, singular_mode_warning(model_, dofs, report) +
                          (held.empty() ? "" : "; " + held + ", and nothing touches"));
    }
    const VecX x_old = a.x, rhs_old = a.ev.system.rhs, no_step = VecX::Zero(dofs.n_prescribed());
    if (stabilisation_.engaged() || pseudo_.active()) {
      // Weak springs (or weak damping) hold a point contact's rocking: a full step swings it
      // far through the contact that stops it, and the next iteration swings it back.
      const Real fraction = contact_.step_fraction_to_contact(a.u, dofs.expand(x_old + dx, a.g) - a.u);
      if (fraction < 1) dx *= std::max(fraction, kMinContactStep);
    }
    a.x = x_old + dx;
    VecX u_new = dofs.expand(a.x, a.g);
    if (sc.step->nlgeom) layout_.relinearise(u_new);
    a.ev = evaluate(sc, a, u_new, no_step);
    if (contact_.wants_line_search(it)) {
      // The root of the residual's projection on dx, from its values at both ends.
      const Real r0 = dx.dot(rhs_old), r1 = dx.dot(a.ev.system.rhs);
      const auto& cc = sc.step->contact_controls;
      const Real eta =
          std::clamp(r0 - r1 != 0 ? r0 / (r0 - r1) : 1, cc.line_search_min, cc.line_search_max);
      if (std::abs(eta - 1) > 1e-3) {
        a.x = x_old + eta * dx;
        u_new = dofs.expand(a.x, a.g);
        if (sc.step->nlgeom) layout_.relinearise(u_new);
        a.ev = evaluate(sc, a, u_new, no_step);
      }
    }
    if (pseudo_.active()) {
      const VecX step = a.x - x_old;
      pseudo_.stepped(a.ev.system.rhs.norm(), step.dot(damping.cwiseProduct(step)));
    }
    const Real c_max = max_abs(u_new - a.u);
    a.u = std::move(u_new);
    const Real q_bar = a.ev.force_components
                           ? a.ev.force_abs_sum / static_cast<Real>(a.ev.force_components)
                           : 0;
    return convergence_->check(it, {q_bar, max_abs(a.ev.system.rhs), c_max, contact_count()});
  }

  /// Contact's verdict on the increment converged at the iterate of `a`: it stands, or goes on
  /// (Iterate) from a contact geometry frozen again at the iterate, or is redone smaller. A
  /// drifted frozen geometry is frozen again up to kMaxRefreezes times, then redone smaller
  /// while the increment limits allow it (beyond the thesis, section 7.1: the answer must meet
  /// the same drift check either way; refreezing saves redoing a sliding increment from its
  /// start); a missed contact is always redone (the cutback fails the step at those limits).
  nonlinear::Verdict judged_by_contact(const StepContext& sc, const Attempt& a, int& refreezes) {
    nonlinear::Verdict converged;
    converged.kind = nonlinear::Verdict::Kind::Converged;
    if (contact_.empty()) return converged;
    const contact::Acceptance acceptance = contact_.accept(a.u, options_.drift_check);
    if (acceptance.accepted) return converged;
    if (acceptance.pair_again && refreezes < kMaxRefreezes) {
      contact_.pair_again();
      ++refreezes;
      return {.kind = nonlinear::Verdict::Kind::Iterate, .reason = acceptance.reason};
    }
    if (!acceptance.required && refreezes < kMaxRefreezes) {
      timed(times_.contact_search, [&] { contact_.refreeze(a.u, u_, threads_); });
      ++refreezes;
      ++drift_refreezes_;
      timed(times_.pattern, [&] { layout_.set_contact_groups(contact_.groups(), *solver_, threads_); });
      return {.kind = nonlinear::Verdict::Kind::Iterate, .reason = acceptance.reason};
    }
    const bool redo_allowed =
        !sc.step->procedure.direct &&
        acceptance.redo_factor * increments_->increment() >= increments_->min_increment() &&
        increments_->attempt() <= sc.controls.max_cutbacks;
    if (acceptance.refreeze_only || (!redo_allowed && !acceptance.required)) return converged;
    if (!acceptance.required) ++drift_redos_;
    return {.kind = nonlinear::Verdict::Kind::Cutback, .cutback_factor = acceptance.redo_factor,
            .reason = acceptance.reason};
  }

  /// The increment converged: its states become the committed ones and its frame is written.
  void commit_increment(const StepContext& sc, Attempt& a, int it) {
    convergence_->commit_increment();
    predictor_.converged(u_, a.u, increments_->increment());
    u_ = a.u;
    elements_.commit();
    contact_.commit();
    if (!links_.empty()) links_.commit(u_, a.ev.internal_force - loads_at(sc, a.t, a.u));
    const int increment_no = increments_->increment_number(), attempt = increments_->attempt();
    const Real dt = increments_->increment();
    const bool at_time_point = increments_->ends_at_time_point();
    increments_->converged(it);

    output::Frame frame = converged_frame(model_, u_, a.ev, sc.step->nlgeom);
    layout_.dofs().add_constraint_forces(frame.RF);
    frame.element_active = sc.step->element_active;
    frame.T = nodal_temperatures(model_, a.dT);
    frame.step = sc.number;
    frame.increment = increment_no;
    frame.step_time = a.t;
    frame.total_time = total_time_start_ + a.t;
    frame.is_step_end = increments_->finished();
    if (sc.step->time_points >= 0) frame.at_time_point = at_time_point;
    if (!contact_.empty()) {
      contact_.write_output(u_, frame);
      max_contact_pressure_ = contact_.max_pressure();
      total_contact_force_ = contact_.total_normal_force();
    }
    for (Index k = 0; k < frame.S.rows(); ++k)
      max_mises_ = std::max(max_mises_, material::von_mises(frame.S.row(k).transpose()));
    Event increment{.kind = Event::Kind::Increment, .step = sc.number,
                    .increment = increment_no, .attempt = attempt, .iteration = it,
                    .step_time = a.t, .total_time = total_time_start_ + a.t, .dt = dt,
                    .contact_elements = contact_count(), .wall_time = wall()};
    if (!contact_.empty()) {
      // The energy the contact stabilisation absorbed beside the strain energy (Abaqus: ALLSD
      // and ALLIE); what the increment commits is the unstabilised equilibrium either way.
      const Real strain_energy = frame.ENER.dot(frame.ip_volume) + a.ev.connector_energy;
      const Real absorbed =
          stabilisation_.absorbed_energy() + (pseudo_.active() ? pseudo_.absorbed_energy() : 0);
      step_stabilisation_energy_ += absorbed;
      increment.stabilisation_energy = absorbed;
      increment.strain_energy = strain_energy;
      if (frame.is_step_end && step_stabilisation_energy_ > 0.01 * std::abs(strain_energy))
        warn(sc.number, "the contact stabilisation absorbed " +
                            std::to_string(step_stabilisation_energy_) + " in step " +
                            std::to_string(sc.number) + ", more than 1 % of the strain energy (" +
                            std::to_string(strain_energy) +
                            "): the path to the step's end differs from the unstabilised one "
                            "where it depends on the path (friction, plasticity); the end state "
                            "of every increment is the unstabilised equilibrium");
    }
    events_.on_event(increment);
    frames_.on_frame(*sc.step, frame);
  }

  /// The increment failed (or contact redoes it): back to the committed state, smaller.
  void cut_back(const StepContext& sc, const Attempt& a, int it,
                const nonlinear::Verdict& verdict) {
    elements_.roll_back();
    contact_.roll_back();
    events_.on_event({.kind = Event::Kind::Cutback, .step = sc.number,
                      .increment = increments_->increment_number(),
                      .attempt = increments_->attempt(), .iteration = it, .step_time = a.t_old,
                      .total_time = total_time_start_ + a.t_old, .dt = increments_->increment(),
                      .contact_elements = contact_count(), .wall_time = wall(),
                      .message = verdict.reason});
    increments_->cut_back(verdict.cutback_factor, verdict.reason);
  }

  void report_iteration(const StepContext& sc, const Attempt& a, int it,
                        const nonlinear::Verdict& verdict) {
    events_.on_event({.kind = Event::Kind::Iteration, .step = sc.number,
                      .increment = increments_->increment_number(),
                      .attempt = increments_->attempt(), .iteration = it, .step_time = a.t,
                      .total_time = total_time_start_ + a.t, .dt = increments_->increment(),
                      .residual = 100 * verdict.residual_ratio,
                      .correction = 100 * verdict.correction_ratio,
                      .contact_elements = contact_count(), .stick = contact_.n_sticking(),
                      .slip = contact_.n_slipping(),
                      .stabilisation = contact_.stabilisation(), .wall_time = wall()});
  }

  void warn(int step, const std::string& message) {
    events_.on_event(
        {.kind = Event::Kind::Warning, .step = step, .wall_time = wall(), .message = message});
  }
  int contact_count() const { return contact_.empty() ? -1 : contact_.n_active(); }

  void report_done() {
    Event done{.kind = Event::Kind::Done, .wall_time = wall(), .status = "converged"};
    done.iterations = total_iterations_;
    done.max_displacement = 0;
    for (int n = 0; n < model_.n_nodes(); ++n)
      done.max_displacement = std::max(done.max_displacement, u_.segment<3>(3 * n).norm());
    done.max_mises = max_mises_;
    done.has_contact = !contact_.empty();
    done.max_contact_pressure = max_contact_pressure_;
    done.total_contact_force = total_contact_force_;
    done.drift_redos = drift_redos_;
    done.drift_refreezes = drift_refreezes_;
    done.times = times_;
    events_.on_event(done);
  }

  const model::Model& model_;
  const NonlinearOptions& options_;
  FrameSink& frames_;
  EventSink& events_;
  const int threads_;
  const Clock::time_point t0_;

  // Committed state of the run
  VecX u_;                       ///< converged displacements
  VecX cloads_prev_, dT_prev_;   ///< concentrated loads and temperatures at the previous step end
  Real total_time_start_ = 0, last_q_bar_ = 0;
  ElementStates elements_;
  contact::ContactSystem contact_;
  bool any_plastic_ = false;

  // Solution machinery
  ConstraintLayout layout_;
  DistanceLinks links_;
  std::unique_ptr<linsolve::LinearSolver> solver_;
  linsolve::SpdSolve spd_;
  LinearElementCache element_cache_;
  std::optional<nonlinear::Convergence> convergence_;
  std::optional<nonlinear::IncrementControl> increments_;
  nonlinear::StaticPredictor predictor_;
  contact::StabilisationSchedule stabilisation_;
  nonlinear::PseudoTransient pseudo_;  ///< of the attempt, where the springs found no way off
  bool retry_stabilised_ = false;  ///< the increment's last attempt failed (with contact)
  bool warned_zero_energy_mode_ = false;
  /// Why the contact stabilisation could not be released in an attempt of the increment being
  /// tried (empty: it could, or it was not needed).
  std::string stabilisation_diagnosis_;

  // Figures for the done event
  PhaseTimes times_;
  int total_iterations_ = 0, drift_redos_ = 0, drift_refreezes_ = 0;
  /// A drift that survives this many refreezes comes from the increment's size: redo it smaller.
  static constexpr int kMaxRefreezes = 3;
  /// The shortest share of a Newton step that stabilised solves take on their way to contact.
  static constexpr Real kMinContactStep = 1e-3;
  Real step_stabilisation_energy_ = 0;
  Real max_mises_ = 0, max_contact_pressure_ = 0, total_contact_force_ = 0;
};

}  // namespace

bool needs_newton(const model::Model& model) {
  if (!model.contact_pairs.empty() || !model.connectors.empty()) return true;
  for (const auto& step : model.steps)
    if (!step.element_active.empty()) return true;  // *MODEL CHANGE, TYPE=ELEMENT
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
  NonlinearStatic(model, options, frames, events).run();
}

}  // namespace kontakt::analysis
