#include "analysis/singular_system.hpp"

namespace kontakt::analysis {

std::string singular_mode_warning(const model::Model& model, const assembly::DofMap& dofs,
                                  const linsolve::SpdSolveReport& report) {
  const int eq = report.singular_equation;
  std::string where = eq >= 0 ? " at " + dofs.describe_unknown(model, dofs.equation_dof(eq)) : "";
  return "the stiffness matrix has a zero-energy mode" + where +
         " (hourglassing of reduced-integration elements, a missing constraint, a body held "
         "only by contact that does not touch or a truss joint free across its bars) that the "
         "loads do not excite; solved with "
         "stabilisation, the displacement in that mode is not determined by the model";
}

SolverError singular_system_error(const model::Model& model, const assembly::DofMap& dofs,
                                  const linsolve::SingularMatrix& e) {
  std::string msg = e.what();
  if (e.equation() >= 0)
    msg += " at " + dofs.describe_unknown(model, dofs.equation_dof(e.equation())) +
           ": it is not held by any element stiffness, contact or boundary condition";
  else
    msg += ": the model has an unconstrained rigid-body mode or a mechanism";
  return SolverError(msg);
}

}  // namespace kontakt::analysis
