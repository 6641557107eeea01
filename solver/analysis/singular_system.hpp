// What the drivers say about a singular stiffness matrix, naming the dof behind the singular
// pivot where the solver could tell which.
#pragma once

#include <string>

#include "assembly/dof_map.hpp"
#include "core/error.hpp"
#include "linsolve/linear_solver.hpp"
#include "linsolve/spd_solve.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// The warning for a zero-energy mode the loads do not excite, which was solved with
/// stabilisation: the displacement in that mode is not determined by the model.
std::string singular_mode_warning(const model::Model& model, const assembly::DofMap& dofs,
                                  const linsolve::SpdSolveReport& report);

/// The error for a singular system whose zero-energy mode the loads excite.
SolverError singular_system_error(const model::Model& model, const assembly::DofMap& dofs,
                                  const linsolve::SingularMatrix& e);

}  // namespace kontakt::analysis
