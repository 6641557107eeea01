// The constraint layout of the current step with its assembly plan and symbolic factorisation,
// shared by the drivers: rebuilt only when a step constrains other dofs than the step before.
#pragma once

#include <memory>

#include "assembly/assembler.hpp"
#include "linsolve/linear_solver.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

class ConstraintLayout {
 public:
  /// Takes `step`'s constraints (the nonlinear ones `in_force`, DofMap's). When their layout
  /// differs from the current one, checks that every body is supported, builds the assembly
  /// plan and reruns the solver's symbolic analysis, and returns true (numeric factorisations
  /// must then be redone).
  bool update(const model::Model& model, const model::Step& step, linsolve::LinearSolver& solver,
              int threads, const std::vector<char>& in_force = {});
  /// Takes this increment's contact groups into the pattern. When they differ from the current
  /// ones, rebuilds the pattern and reruns the symbolic analysis, and returns true.
  bool set_contact_groups(const std::vector<std::vector<int>>& groups,
                          linsolve::LinearSolver& solver, int threads);
  /// Solves the nonlinear constraints for their dependent dofs in `u` and linearises them
  /// there (DofMap::relinearise); the pattern stays.
  void relinearise(VecX& u) { dofs_->relinearise(u); }
  const assembly::DofMap& dofs() const { return *dofs_; }
  const assembly::AssemblyPlan& plan() const { return *plan_; }

 private:
  std::unique_ptr<assembly::DofMap> dofs_;
  std::unique_ptr<assembly::AssemblyPlan> plan_;
};

}  // namespace kontakt::analysis
