#include "assembly/dof_map.hpp"

#include <algorithm>
#include <map>

namespace kontakt::assembly {

namespace {

enum class Kind : char { Inactive, Free, Prescribed, Dependent };

const char* component_name(int c) { return c == 0 ? "x" : c == 1 ? "y" : "z"; }

/// Dofs of nodes that belong to at least one element: the others carry no stiffness.
std::vector<char> attached_dofs(const model::Model& model) {
  std::vector<char> attached(3 * static_cast<std::size_t>(model.n_nodes()), 0);
  for (const auto& el : model.mesh.elements)
    for (int n : el.nodes)
      for (int c = 0; c < 3; ++c) attached[3 * n + c] = 1;
  return attached;
}

/// Terms sorted by unknown with repeated references to the same unknown summed.
std::vector<DofTerm> merged(std::vector<DofTerm> terms) {
  std::sort(terms.begin(), terms.end(), [](const DofTerm& a, const DofTerm& b) {
    return std::tie(a.is_prescribed, a.index) < std::tie(b.is_prescribed, b.index);
  });
  std::vector<DofTerm> out;
  for (const DofTerm& t : terms) {
    if (!out.empty() && out.back().index == t.index && out.back().is_prescribed == t.is_prescribed)
      out.back().coef += t.coef;
    else
      out.push_back(t);
  }
  return out;
}

}  // namespace

DofMap::DofMap(const model::Model& model, const std::vector<model::Boundary>& boundaries) {
  const int n = 3 * model.n_nodes();
  frames_ = model.local_frames;
  const std::vector<char> attached = attached_dofs(model);
  std::vector<Kind> kind(n);
  for (int d = 0; d < n; ++d) kind[d] = attached[d] ? Kind::Free : Kind::Inactive;

  prescribed_slot_.assign(n, -1);
  for (const auto& bc : boundaries) {
    const int d = 3 * bc.node + bc.dof;
    if (prescribed_slot_[d] >= 0) continue;  // the step's value list resolves duplicates
    prescribed_slot_[d] = static_cast<int>(prescribed_dof_.size());
    prescribed_dof_.push_back(d);
    kind[d] = Kind::Prescribed;
  }

  // Dependent dofs: the first term of each equation, expressed by the remaining terms.
  using model::Equation;
  std::map<int, const Equation*> dependent_of;
  for (const auto& eq : model.equations) {
    const auto& lead = eq.terms.front();
    const int d = 3 * lead.node + lead.dof;
    if (kind[d] == Kind::Prescribed)
      throw InputError(eq.where, eq.keyword,
                       "the dependent dof of this constraint (" + describe_unknown(model, d) +
                           ") is also prescribed by *BOUNDARY in this step");
    if (dependent_of.count(d)) {
      const Equation& first = *dependent_of.at(d);
      throw InputError(eq.where, eq.keyword,
                       "dof " + describe_unknown(model, d) +
                           " is the dependent term of two equations (the other: " +
                           first.keyword + " at " + first.where.file + ":" +
                           std::to_string(first.where.line) + ")");
    }
    dependent_of[d] = &eq;
    kind[d] = Kind::Dependent;
  }
  for (const auto& eq : model.equations)  // ccx's *TIE ties global components
    for (const auto& term : eq.terms)
      if (eq.keyword != "*EQUATION" && frames_.contains(term.node))
        throw InputError(eq.where, eq.keyword,
                         "node " + std::to_string(model.mesh.node_ids[term.node]) +
                             " has a *TRANSFORM; tying transformed nodes is not supported");
  for (const auto& eq : model.equations)
    for (std::size_t k = 1; k < eq.terms.size(); ++k) {
      const int d = 3 * eq.terms[k].node + eq.terms[k].dof;
      if (kind[d] == Kind::Inactive) kind[d] = Kind::Free;  // tied in through the equation
    }

  equation_dof_.clear();
  std::vector<int> eq_of(n, -1);
  for (int d = 0; d < n; ++d)
    if (kind[d] == Kind::Free) {
      eq_of[d] = static_cast<int>(equation_dof_.size());
      equation_dof_.push_back(d);
    }
  n_equations_ = static_cast<int>(equation_dof_.size());

  // Expand each dof into terms over free equations and prescribed slots; dependent dofs are
  // resolved recursively (chains of equations), with cycle detection.
  std::vector<std::vector<DofTerm>> expr(n);
  std::vector<char> state(n, 0);  // 0 unvisited, 1 in progress, 2 done
  auto resolve = [&](auto&& self, int d) -> const std::vector<DofTerm>& {
    if (state[d] == 2) return expr[d];
    if (state[d] == 1)
      throw InputError(dependent_of.at(d)->where, dependent_of.at(d)->keyword,
                       "equations form a cycle through " + describe_unknown(model, d) +
                           " (each dependent dof is expressed through the next)");
    state[d] = 1;
    std::vector<DofTerm> out;
    switch (kind[d]) {
      case Kind::Inactive: break;
      case Kind::Free: out.push_back({eq_of[d], 1.0, false}); break;
      case Kind::Prescribed: out.push_back({prescribed_slot_[d], 1.0, true}); break;
      case Kind::Dependent: {
        const auto& eq = *dependent_of.at(d);
        const Real lead = eq.terms.front().coef;
        if (lead == 0)
          throw InputError(eq.where, eq.keyword, "the first coefficient must not be zero");
        for (std::size_t k = 1; k < eq.terms.size(); ++k) {
          const int other = 3 * eq.terms[k].node + eq.terms[k].dof;
          for (const DofTerm& t : self(self, other))
            out.push_back({t.index, -eq.terms[k].coef / lead * t.coef, t.is_prescribed});
        }
        break;
      }
    }
    expr[d] = merged(std::move(out));
    state[d] = 2;
    return expr[d];
  };

  // Global row d of a transformed node: sum over its local unknowns j of R(c, j) * u_j.
  auto row = [&](int d) {
    const auto frame = frames_.find(d / 3);
    if (frame == frames_.end()) return resolve(resolve, d);
    std::vector<DofTerm> out;
    for (int j = 0; j < 3; ++j) {
      const Real r = frame->second(d % 3, j);
      if (r == 0) continue;
      for (const DofTerm& t : resolve(resolve, 3 * (d / 3) + j))
        out.push_back({t.index, r * t.coef, t.is_prescribed});
    }
    return merged(std::move(out));
  };

  start_.assign(n + 1, 0);
  terms_.clear();
  for (int d = 0; d < n; ++d) {
    const std::vector<DofTerm> e = row(d);
    terms_.insert(terms_.end(), e.begin(), e.end());
    start_[d + 1] = static_cast<int>(terms_.size());
  }
}

Real DofMap::unknown_value(const VecX& u, int unknown) const {
  const auto frame = frames_.find(unknown / 3);
  if (frame == frames_.end()) return u[unknown];
  return frame->second.col(unknown % 3).dot(u.segment<3>(3 * (unknown / 3)));
}

const Mat3* DofMap::local_frame(int node) const {
  const auto frame = frames_.find(node);
  return frame == frames_.end() ? nullptr : &frame->second;
}

bool DofMap::is_free(int dof) const {
  return !frames_.contains(dof / 3) && start_[dof + 1] - start_[dof] == 1 &&
         !terms_[start_[dof]].is_prescribed && equation_dof_[terms_[start_[dof]].index] == dof;
}

Real DofMap::offset(int dof, const VecX& prescribed_values) const {
  Real g = 0;
  for (auto t = terms_begin(dof); t != terms_end(dof); ++t)
    if (t->is_prescribed) g += t->coef * prescribed_values[t->index];
  return g;
}

VecX DofMap::expand(const VecX& x, const VecX& prescribed_values) const {
  VecX u = VecX::Zero(n_dofs());
  for (int d = 0; d < n_dofs(); ++d) {
    Real v = 0;
    for (auto t = terms_begin(d); t != terms_end(d); ++t)
      v += t->coef * (t->is_prescribed ? prescribed_values[t->index] : x[t->index]);
    u[d] = v;
  }
  return u;
}

bool DofMap::same_structure(const DofMap& other) const {
  if (start_ != other.start_ || terms_.size() != other.terms_.size()) return false;
  for (std::size_t k = 0; k < terms_.size(); ++k)
    if (terms_[k].index != other.terms_[k].index ||
        terms_[k].is_prescribed != other.terms_[k].is_prescribed ||
        terms_[k].coef != other.terms_[k].coef)
      return false;
  return true;
}

std::string DofMap::describe(const model::Model& model, int dof) const {
  return "node " + std::to_string(model.mesh.node_ids[dof / 3]) + " dof " +
         component_name(dof % 3);
}

std::string DofMap::describe_unknown(const model::Model& model, int unknown) const {
  if (!frames_.contains(unknown / 3)) return describe(model, unknown);
  return "node " + std::to_string(model.mesh.node_ids[unknown / 3]) + " local dof " +
         std::to_string(unknown % 3 + 1);
}

}  // namespace kontakt::assembly
