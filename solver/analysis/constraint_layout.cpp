#include "analysis/constraint_layout.hpp"

#include "analysis/support_check.hpp"

namespace kontakt::analysis {

bool ConstraintLayout::update(const model::Model& model, const model::Step& step,
                              linsolve::LinearSolver& solver, int threads,
                              const std::vector<char>& in_force) {
  auto step_dofs =
      std::make_unique<assembly::DofMap>(model, step.boundaries, step.element_active, in_force);
  if (dofs_ && dofs_->same_structure(*step_dofs)) return false;
  dofs_ = std::move(step_dofs);
  check_bodies_supported(model, *dofs_);
  plan_ = std::make_unique<assembly::AssemblyPlan>(
      assembly::make_plan(model, *dofs_, /*symmetric=*/true, threads));
  solver.analyze(plan_->pattern);
  return true;
}

bool ConstraintLayout::set_contact_groups(const std::vector<std::vector<int>>& groups,
                                          linsolve::LinearSolver& solver, int threads) {
  if (plan_->groups == groups) return false;
  assembly::set_groups(*plan_, groups, threads);
  solver.analyze(plan_->pattern);
  return true;
}

}  // namespace kontakt::analysis
