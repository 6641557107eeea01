// Sparsity pattern of the reduced stiffness T^T K T, built once per constraint structure and
// reused for every assembly while that structure holds.
#pragma once

#include <vector>

#include "assembly/dof_map.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::assembly {

/// Free equations each element touches through its dofs (sorted, unique), in CSR form.
struct ElementEquations {
  std::vector<Index> start;  ///< element e owns eqs[start[e] .. start[e+1])
  std::vector<int> eqs;
};
ElementEquations element_equations(const model::Model& model, const DofMap& dofs);
/// The same for arbitrary node groups (contact groups: slave nodes with a master face).
ElementEquations group_equations(const std::vector<std::vector<int>>& groups, const DofMap& dofs);
/// `a` followed by `b`: the lists of both, as for one combined set of elements.
ElementEquations concatenate(const ElementEquations& a, const ElementEquations& b);

/// Compressed sparse column pattern. When `upper` is set only rows <= column are stored
/// (the symmetric storage CHOLMOD takes); otherwise the full pattern (UMFPACK).
struct SparsePattern {
  int n = 0;
  bool upper = true;
  std::vector<Index> col_start;  ///< n + 1 entries
  std::vector<int> row_index;    ///< sorted within each column

  Index nnz() const { return col_start.empty() ? 0 : col_start.back(); }
  /// Position of (row, col) in the value array; -1 when the entry is not in the pattern.
  Index find(int row, int col) const;
};

SparsePattern build_pattern(const ElementEquations& element_eqs, int n_equations, bool upper,
                            int threads);

/// Groups of elements that share no equation, so each group can be scattered in parallel
/// without locks. Greedy colouring; order within a colour follows element order.
std::vector<std::vector<int>> colour_elements(const ElementEquations& element_eqs,
                                              int n_equations);

}  // namespace kontakt::assembly
