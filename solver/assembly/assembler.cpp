#include "assembly/assembler.hpp"

#include <algorithm>
#include <atomic>

#include "core/parallel.hpp"

namespace kontakt::assembly {

namespace {
std::uint64_t next_generation() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}
}  // namespace

AssemblyPlan make_plan(const model::Model& model, const DofMap& dofs, bool symmetric,
                       int threads) {
  AssemblyPlan plan;
  plan.generation = next_generation();
  plan.dofs = &dofs;
  plan.element_eqs = element_equations(model, dofs);
  plan.colours = colour_elements(plan.element_eqs, dofs.n_equations());
  if (!model.connectors.empty()) {  // springs and gaps: node pairs after the elements
    std::vector<std::vector<int>> pairs;
    for (const auto& c : model.connectors) pairs.push_back({c.nodes[0], c.nodes[1]});
    plan.element_eqs = concatenate(plan.element_eqs, group_equations(pairs, dofs));
  }
  plan.pattern = build_pattern(plan.element_eqs, dofs.n_equations(), symmetric, threads);
  return plan;
}

void set_groups(AssemblyPlan& plan, std::vector<std::vector<int>> groups, int threads) {
  plan.groups = std::move(groups);
  const ElementEquations all =
      plan.groups.empty() ? plan.element_eqs
                          : concatenate(plan.element_eqs, group_equations(plan.groups, *plan.dofs));
  plan.pattern = build_pattern(all, plan.dofs->n_equations(), plan.pattern.upper, threads);
  plan.generation = next_generation();
}

namespace {

/// Adds one element's (or node group's) K and f into the reduced system through the dof
/// expressions.
void scatter_element(const std::vector<int>& nodes, const DofMap& dofs,
                     const SparsePattern& pattern, const VecX& prescribed, const MatX& K,
                     const VecX& f, ReducedSystem& out) {
  const int n_local = 3 * static_cast<int>(nodes.size());
  auto dof_of = [&](int a) { return 3 * nodes[a / 3] + a % 3; };
  for (int a = 0; a < n_local; ++a) {
    const int da = dof_of(a);
    for (auto ta = dofs.terms_begin(da); ta != dofs.terms_end(da); ++ta) {
      if (ta->is_prescribed) continue;
      const int row = ta->index;
      out.rhs[row] += ta->coef * f[a];
      for (int b = 0; b < n_local; ++b) {
        const Real kab = K(a, b);
        if (kab == 0) continue;
        const int db = dof_of(b);
        for (auto tb = dofs.terms_begin(db); tb != dofs.terms_end(db); ++tb) {
          const Real v = ta->coef * tb->coef * kab;
          if (tb->is_prescribed) {
            out.rhs[row] -= v * prescribed[tb->index];
            continue;
          }
          const int col = tb->index;
          if (!pattern.upper) {
            out.values[pattern.find(row, col)] += v;
          } else if (!out.skew.empty()) {  // unsymmetric: both halves, split by symmetry
            const Index k = pattern.find(std::min(row, col), std::max(row, col));
            if (row == col) {
              out.values[k] += v;
            } else {
              out.values[k] += 0.5 * v;
              out.skew[k] += row < col ? 0.5 * v : -0.5 * v;
            }
          } else if (row <= col) {
            out.values[pattern.find(row, col)] += v;
          }
        }
      }
    }
  }
}

}  // namespace

void assemble(const model::Model& model, const AssemblyPlan& plan,
              const VecX& prescribed_values, const ElementKernel& kernel, int threads,
              ReducedSystem& out) {
  const DofMap& dofs = *plan.dofs;
  out.values.assign(plan.pattern.nnz(), 0.0);
  out.rhs = VecX::Zero(dofs.n_equations());
  const auto& elements = model.mesh.elements;
  for (const auto& colour : plan.colours) {
    parallel_chunks(colour.size(), threads, [&](std::size_t begin, std::size_t end, int) {
      MatX K;
      VecX f;
      for (std::size_t k = begin; k < end; ++k) {
        const int e = colour[k];
        kernel(e, K, f);
        scatter_element(elements[e].nodes, dofs, plan.pattern, prescribed_values, K, f, out);
      }
    });
  }
}

void assemble_loads(const model::Model& model, const AssemblyPlan& plan,
                    const ElementLoadKernel& kernel, int threads, VecX& rhs) {
  const DofMap& dofs = *plan.dofs;
  rhs = VecX::Zero(dofs.n_equations());
  const auto& elements = model.mesh.elements;
  for (const auto& colour : plan.colours) {
    parallel_chunks(colour.size(), threads, [&](std::size_t begin, std::size_t end, int) {
      VecX f;
      for (std::size_t k = begin; k < end; ++k) {
        const int e = colour[k];
        kernel(e, f);
        const auto& nodes = elements[e].nodes;
        for (std::size_t a = 0; a < 3 * nodes.size(); ++a) {
          const int d = 3 * nodes[a / 3] + static_cast<int>(a % 3);
          for (auto t = dofs.terms_begin(d); t != dofs.terms_end(d); ++t)
            if (!t->is_prescribed) rhs[t->index] += t->coef * f[a];
        }
      }
    });
  }
}

void scatter_nodes(const AssemblyPlan& plan, const std::vector<int>& nodes,
                   const VecX& prescribed_values, const MatX& K, const VecX& f,
                   ReducedSystem& out) {
  scatter_element(nodes, *plan.dofs, plan.pattern, prescribed_values, K, f, out);
}

void scatter_groups(const AssemblyPlan& plan, const VecX& prescribed_values,
                    const std::vector<const MatX*>& K, const std::vector<const VecX*>& f,
                    ReducedSystem& out) {
  for (std::size_t g = 0; g < plan.groups.size(); ++g)
    scatter_element(plan.groups[g], *plan.dofs, plan.pattern, prescribed_values, *K[g], *f[g], out);
}

void add_nodal_forces(const DofMap& dofs, const VecX& f, VecX& rhs) {
  for (int d = 0; d < dofs.n_dofs(); ++d) {
    if (f[d] == 0) continue;
    for (auto t = dofs.terms_begin(d); t != dofs.terms_end(d); ++t)
      if (!t->is_prescribed) rhs[t->index] += t->coef * f[d];
  }
}

}  // namespace kontakt::assembly
