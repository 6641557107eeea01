#include "assembly/sparse_pattern.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

#include "core/parallel.hpp"

namespace kontakt::assembly {

namespace {

/// Free equations of the dofs of each node list `nodes_of(i)`, i < n, sorted and unique.
template <class NodesOf>
ElementEquations equations_of(std::size_t n, NodesOf&& nodes_of, const DofMap& dofs) {
  ElementEquations out;
  out.start.assign(n + 1, 0);
  std::vector<int> scratch;
  for (std::size_t e = 0; e < n; ++e) {
    scratch.clear();
    for (int node : nodes_of(e))
      for (int c = 0; c < 3; ++c)
        for (auto t = dofs.terms_begin(3 * node + c); t != dofs.terms_end(3 * node + c); ++t)
          if (!t->is_prescribed) scratch.push_back(t->index);
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    out.eqs.insert(out.eqs.end(), scratch.begin(), scratch.end());
    out.start[e + 1] = static_cast<Index>(out.eqs.size());
  }
  return out;
}

}  // namespace

ElementEquations element_equations(const model::Model& model, const DofMap& dofs) {
  const auto& elements = model.mesh.elements;
  return equations_of(elements.size(), [&](std::size_t e) -> const std::vector<int>& {
    return elements[e].nodes;
  }, dofs);
}

ElementEquations group_equations(const std::vector<std::vector<int>>& groups, const DofMap& dofs) {
  return equations_of(groups.size(), [&](std::size_t g) -> const std::vector<int>& {
    return groups[g];
  }, dofs);
}

ElementEquations concatenate(const ElementEquations& a, const ElementEquations& b) {
  ElementEquations out = a;
  out.eqs.insert(out.eqs.end(), b.eqs.begin(), b.eqs.end());
  const Index shift = a.start.back();
  for (std::size_t k = 1; k < b.start.size(); ++k) out.start.push_back(b.start[k] + shift);
  return out;
}

Index SparsePattern::find(int row, int col) const {
  const auto begin = row_index.begin() + col_start[col];
  const auto end = row_index.begin() + col_start[col + 1];
  const auto it = std::lower_bound(begin, end, row);
  if (it == end || *it != row) return -1;
  return it - row_index.begin();
}

SparsePattern build_pattern(const ElementEquations& element_eqs, int n_equations, bool upper,
                            int threads) {
  // Transpose the element -> equation lists into equation -> element lists.
  const std::size_t n_elements = element_eqs.start.size() - 1;
  std::vector<Index> eq_start(n_equations + 1, 0);
  for (int eq : element_eqs.eqs) ++eq_start[eq + 1];
  for (int i = 0; i < n_equations; ++i) eq_start[i + 1] += eq_start[i];
  std::vector<int> eq_elements(eq_start.back());
  {
    std::vector<Index> fill(eq_start.begin(), eq_start.end() - 1);
    for (std::size_t e = 0; e < n_elements; ++e)
      for (Index k = element_eqs.start[e]; k < element_eqs.start[e + 1]; ++k)
        eq_elements[fill[element_eqs.eqs[k]]++] = static_cast<int>(e);
  }

  // Column j's rows = union of the equation lists of the elements touching j.
  std::vector<std::vector<int>> columns(n_equations);
  parallel_chunks(n_equations, threads, [&](std::size_t begin, std::size_t end, int) {
    std::vector<int> mark(n_equations, -1);
    for (std::size_t j = begin; j < end; ++j) {
      auto& rows = columns[j];
      for (Index k = eq_start[j]; k < eq_start[j + 1]; ++k) {
        const int e = eq_elements[k];
        for (Index m = element_eqs.start[e]; m < element_eqs.start[e + 1]; ++m) {
          const int i = element_eqs.eqs[m];
          if ((upper && i > static_cast<int>(j)) || mark[i] == static_cast<int>(j)) continue;
          mark[i] = static_cast<int>(j);
          rows.push_back(i);
        }
      }
      // A free dof no element reaches still needs its diagonal, so a zero pivot is detected.
      if (mark[j] != static_cast<int>(j)) rows.push_back(static_cast<int>(j));
      std::sort(rows.begin(), rows.end());
    }
  });

  SparsePattern p;
  p.n = n_equations;
  p.upper = upper;
  p.col_start.assign(n_equations + 1, 0);
  for (int j = 0; j < n_equations; ++j)
    p.col_start[j + 1] = p.col_start[j] + static_cast<Index>(columns[j].size());
  p.row_index.resize(p.col_start.back());
  for (int j = 0; j < n_equations; ++j) {
    std::copy(columns[j].begin(), columns[j].end(), p.row_index.begin() + p.col_start[j]);
    std::vector<int>().swap(columns[j]);
  }
  return p;
}

std::vector<std::vector<int>> colour_elements(const ElementEquations& element_eqs,
                                              int n_equations) {
  // Each equation remembers the colours already used by elements touching it (64 per word);
  // an element takes the lowest colour free in all of its equations.
  const std::size_t n_elements = element_eqs.start.size() - 1;
  std::vector<std::vector<std::uint64_t>> used(1, std::vector<std::uint64_t>(n_equations, 0));
  std::vector<std::vector<int>> colours;
  for (std::size_t e = 0; e < n_elements; ++e) {
    for (std::size_t word = 0;; ++word) {
      if (word == used.size()) used.emplace_back(n_equations, 0);
      std::uint64_t taken = 0;
      for (Index k = element_eqs.start[e]; k < element_eqs.start[e + 1]; ++k)
        taken |= used[word][element_eqs.eqs[k]];
      if (taken == ~std::uint64_t{0}) continue;
      const int bit = std::countr_one(taken);
      const std::size_t colour = 64 * word + bit;
      for (Index k = element_eqs.start[e]; k < element_eqs.start[e + 1]; ++k)
        used[word][element_eqs.eqs[k]] |= std::uint64_t{1} << bit;
      if (colours.size() <= colour) colours.resize(colour + 1);
      colours[colour].push_back(static_cast<int>(e));
      break;
    }
  }
  return colours;
}

}  // namespace kontakt::assembly
