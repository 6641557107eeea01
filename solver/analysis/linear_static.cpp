// Linear static driver. Per step:
//   1. constraints -> DofMap; a new pattern and symbolic analysis only if their layout changed
//   2. assemble K and the thermal loads element by element, add *CLOAD and *DLOAD forces
//   3. factorise (skipped when K and the constraint layout equal the previous step's) and solve
//   4. recover strains, stresses and nodal forces, and hand the frame to the writers
#include "analysis/linear_static.hpp"

#include <chrono>
#include <cmath>
#include <memory>

#include "analysis/element_access.hpp"
#include "analysis/singular_system.hpp"
#include "analysis/small_strain_frame.hpp"
#include "analysis/step_loads.hpp"
#include "analysis/constraint_layout.hpp"
#include "assembly/assembler.hpp"
#include "core/parallel.hpp"
#include "element/solid_linear.hpp"
#include "linsolve/linear_solver.hpp"
#include "linsolve/spd_solve.hpp"
#include "material/von_mises.hpp"

namespace kontakt::analysis {

namespace {

using Clock = std::chrono::steady_clock;

/// Rejects what a linear analysis cannot represent, naming the step.
void require_linear(const model::Model& model) {
  for (const auto& step : model.steps)
    if (step.nlgeom)
      throw InputError(step.where, "*STEP",
                       "NLGEOM (geometric nonlinearity) is not supported yet");
  if (model.steps.empty())
    throw InputError({model.source_file, 0}, "*STEP", "the deck defines no step");
}


}  // namespace

void run_linear_static(const model::Model& model, const RunOptions& options, FrameSink& frames,
                       EventSink& events) {
  require_linear(model);
  const int threads = resolve_threads(options.threads);
  const auto t0 = Clock::now();
  auto wall = [&] { return std::chrono::duration<Real>(Clock::now() - t0).count(); };

  // Reused across steps while the constraint layout holds; K does not change in a linear model
  // unless its elastic constants follow a temperature field the steps change.
  ConstraintLayout layout;
  const bool stiffness_follows_temperature = any_temperature_dependent_stiffness(model);
  auto solver = linsolve::make_cholmod_solver();
  linsolve::SpdSolve spd(*solver);
  bool factorised = false;

  Real total_time = 0, max_u = 0, max_mises = 0;
  VecX u_previous = VecX::Zero(3 * model.n_nodes());
  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const model::Step& step = model.steps[s];
    const int step_no = static_cast<int>(s) + 1;
    const auto stop_if_cancelled = [&](const char* before) {
      if (options.cancel && options.cancel->load())
        throw Cancelled("cancelled in step " + std::to_string(step_no) + " before " + before);
    };
    stop_if_cancelled("its assembly");
    events.on_event({.kind = Event::Kind::Step, .step = step_no, .wall_time = wall()});
    const Real period = step.procedure.period;
    total_time += period;

    // *CHANGE SOLID SECTION: another material is another stiffness.
    const bool sections_changed =
        s > 0 && step.element_sections != model.steps[s - 1].element_sections;
    if (layout.update(model, step, *solver, threads) || stiffness_follows_temperature ||
        sections_changed)
      factorised = false;
    const assembly::DofMap& dofs = layout.dofs();
    const assembly::AssemblyPlan& plan = layout.plan();

    const VecX dT = temperature_change(model, step);
    const bool has_thermal_strain = dT.size() > 0 && dT.cwiseAbs().maxCoeff() > 0;
    // A linear step is solved once, at its end: every load at its full value.
    const VecX g =
        prescribed_values(model, step, dofs, period, total_time, 1.0, u_previous, u_previous);
    assembly::ReducedSystem system;
    assembly::assemble(
        model, plan, g,
        [&](int e, MatX& K, VecX& f) {
          const auto& el = model.mesh.elements[e];
          naming_element(el, [&] {
            const MatX3 X = element_coords(model, el);
            const auto mat = element_material(model, el, &step);
            const VecX dTe = element_values(el, dT);
            element::linear_stiffness(el.type, X, mat, dTe, K);
            if (has_thermal_strain && !mat.expansion.empty())
              element::thermal_load(el.type, X, mat, dTe, f);
            else
              f = VecX::Zero(K.rows());
            // An initial stress is a load of -integral(B^T sigma0): u balances what it leaves.
            if (const MatX* sigma0 = element_initial_stress(model, el)) {
              VecX f0;
              element::initial_stress_force(el.type, X, *sigma0, f0);
              f -= f0;
            }
          });
        },
        threads, system);
    const VecX f_ext = external_forces(model, step, period, total_time, 1.0);
    require_loads_reach_elements(model, dofs, f_ext);
    assembly::add_nodal_forces(dofs, f_ext, system.rhs);

    linsolve::SpdSolveReport report;
    VecX x;
    stop_if_cancelled("the factorisation");
    try {
      if (!factorised) spd.factorise(plan.pattern, system.values, report);
      factorised = true;
      stop_if_cancelled("the solve");
      x = spd.solve(plan.pattern, system.values, system.rhs, report);
    } catch (const linsolve::SingularMatrix& e) {
      throw singular_system_error(model, dofs, e);
    }
    if (report.stabilised)
      events.on_event({.kind = Event::Kind::Warning, .step = step_no, .wall_time = wall(),
                       .message = singular_mode_warning(model, dofs, report)});
    const VecX u = dofs.expand(x, g);
    u_previous = u;

    output::Frame frame = small_strain_frame(model, step, u, dT, threads);
    dofs.add_constraint_forces(frame.RF);
    frame.T = nodal_temperatures(model, dT);
    frame.step = step_no;
    frame.increment = 1;
    frame.step_time = period;
    frame.total_time = total_time;
    frame.is_step_end = true;
    for (Index n = 0; n < frame.U.rows(); ++n) max_u = std::max(max_u, frame.U.row(n).norm());
    for (Index k = 0; k < frame.S.rows(); ++k) max_mises = std::max(max_mises, material::von_mises(frame.S.row(k).transpose()));
    events.on_event({.kind = Event::Kind::Increment, .step = step_no, .increment = 1,
                     .attempt = 1, .iteration = 1, .step_time = period,
                     .total_time = total_time, .dt = period, .wall_time = wall()});
    frames.on_frame(step, frame);
  }
  Event done{.kind = Event::Kind::Done, .wall_time = wall(), .status = "converged"};
  done.iterations = static_cast<int>(model.steps.size());
  done.max_displacement = max_u;
  done.max_mises = max_mises;
  events.on_event(done);
}

}  // namespace kontakt::analysis
