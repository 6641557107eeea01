#include "assembly/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "assembly/nonlinear_constraint.hpp"

namespace kontakt::assembly {

namespace {

enum class Kind : char { Inactive, Free, Prescribed, Dependent };

const char* component_name(int c) { return c == 0 ? "x" : c == 1 ? "y" : "z"; }

/// Dofs of nodes that belong to at least one element or connector: the others carry no
/// stiffness.
std::vector<char> attached_dofs(const model::Model& model, const std::vector<char>& active) {
  std::vector<char> attached(3 * static_cast<std::size_t>(model.n_nodes()), 0);
  for (std::size_t e = 0; e < model.mesh.elements.size(); ++e) {
    if (!active.empty() && !active[e]) continue;
    for (int n : model.mesh.elements[e].nodes)
      for (int c = 0; c < 3; ++c) attached[3 * n + c] = 1;
  }
  for (const auto& connector : model.connectors)
    for (int n : connector.nodes)
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

DofMap::DofMap(const model::Model& model, const std::vector<model::Boundary>& boundaries,
               const std::vector<char>& active_elements, const std::vector<char>& in_force)
    : model_(&model) {
  const int n = 3 * model.n_nodes();
  frames_ = model.local_frames;
  const std::vector<char> attached = attached_dofs(model, active_elements);
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
  // Nonlinear constraints: dependent dofs as an equation's; their other dofs are unknowns.
  std::map<int, int> nonlinear_of;  // dependent dof -> constraint
  const auto& constraints = model.nonlinear_constraints;
  const auto enforced = [&](std::size_t i) { return in_force.empty() || in_force[i]; };
  for (int i = 0; i < static_cast<int>(constraints.size()); ++i) {
    if (!enforced(static_cast<std::size_t>(i))) continue;
    const model::NonlinearConstraint& c = constraints[static_cast<std::size_t>(i)];
    const std::vector<ConstraintDof> cdofs = constraint_dofs(c);
    for (const ConstraintDof& cd : cdofs)
      if (frames_.contains(cd.node))
        throw InputError(c.where, c.keyword,
                         "node " + std::to_string(model.mesh.node_ids[cd.node]) +
                             " has a *TRANSFORM; nonlinear constraints on transformed nodes are "
                             "not supported");
    const int d = 3 * cdofs.front().node + cdofs.front().component;
    if (kind[d] == Kind::Prescribed)
      throw InputError(c.where, c.keyword,
                       "the dependent dof of this constraint (" + describe(model, d) +
                           ") is also prescribed by *BOUNDARY in this step");
    if (kind[d] == Kind::Dependent)
      throw InputError(c.where, c.keyword,
                       "dof " + describe(model, d) +
                           " is the dependent dof of this and of another constraint (a node in "
                           "two rigid bodies, or in a rigid body and an *MPC or *EQUATION)");
    kind[d] = Kind::Dependent;
    nonlinear_of[d] = i;
  }
  for (std::size_t i = 0; i < constraints.size(); ++i)
    for (const ConstraintDof& cd : enforced(i) ? constraint_dofs(constraints[i]) : std::vector<ConstraintDof>{})
      if (kind[3 * cd.node + cd.component] == Kind::Inactive)
        kind[3 * cd.node + cd.component] = Kind::Free;  // a reference or rotation node

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
  // Rows that relinearise() updates: nonlinear constraints' and those following them.
  std::vector<char>& moving = moving_dof_;
  moving.assign(n, 0);
  nonlinear_rows_.clear();
  follower_rows_.clear();
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
        if (const auto nl = nonlinear_of.find(d); nl != nonlinear_of.end()) {
          // One term per other dof, in constraint_dofs order, unmerged: relinearise() keeps
          // their coefficients current.
          const model::NonlinearConstraint& c = constraints[static_cast<std::size_t>(nl->second)];
          const std::vector<ConstraintDof> cdofs = constraint_dofs(c);
          VecX gradient;
          constraint_value(c, model.mesh.coords, VecX::Zero(n), &gradient);
          if (gradient[0] == 0)
            throw InputError(c.where, c.keyword,
                             "the constraint does not depend on its dependent dof (" +
                                 describe(model, d) + ") in the undeformed configuration");
          NonlinearRow row{.dof = d, .constraint = nl->second, .other_dofs = {}, .elementless = {}};
          for (std::size_t k = 1; k < cdofs.size(); ++k) {
            const int other = 3 * cdofs[k].node + cdofs[k].component;
            if (kind[other] == Kind::Dependent)
              throw InputError(c.where, c.keyword,
                               describe(model, other) +
                                   " of this constraint is the dependent dof of another "
                                   "constraint or equation; nonlinear constraints cannot be "
                                   "chained");
            const DofTerm t = self(self, other).front();
            out.push_back({t.index, -gradient[static_cast<Index>(k)] / gradient[0], t.is_prescribed});
            row.other_dofs.push_back(other);
            row.elementless.push_back(!attached[other]);
          }
          nonlinear_rows_.push_back(std::move(row));
          moving[d] = 1;
          expr[d] = std::move(out);
          state[d] = 2;
          return expr[d];
        }
        const auto& eq = *dependent_of.at(d);
        const Real lead = eq.terms.front().coef;
        if (lead == 0)
          throw InputError(eq.where, eq.keyword, "the first coefficient must not be zero");
        FollowerRow follower{.dof = d, .sources = {}};
        bool follows = false;
        for (std::size_t k = 1; k < eq.terms.size(); ++k) {
          const int other = 3 * eq.terms[k].node + eq.terms[k].dof;
          const Real c = -eq.terms[k].coef / lead;
          for (const DofTerm& t : self(self, other))
            out.push_back({t.index, c * t.coef, t.is_prescribed});
          follower.sources.emplace_back(other, c);
          follows |= moving[other] != 0;
        }
        if (follows) {  // a term moves with a nonlinear constraint: so does this row
          for (const auto& [dof, c] : follower.sources)
            if (frames_.contains(dof / 3) || frames_.contains(d / 3))
              throw InputError(eq.where, eq.keyword,
                               "this equation follows a nonlinear constraint (*RIGID BODY or "
                               "*MPC) and has a term at a node with a *TRANSFORM "
                               "(" + describe_unknown(model, dof) + "): not supported");
          follower_rows_.push_back(std::move(follower));
          moving[d] = 1;
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
  row_constant_.assign(n, 0);
}

void DofMap::relinearise(VecX& u) {
  const MatX3& coords = model_->mesh.coords;
  VecX gradient;
  for (NonlinearRow& row : nonlinear_rows_) {
    const model::NonlinearConstraint& c =
        model_->nonlinear_constraints[static_cast<std::size_t>(row.constraint)];
    const int d = row.dof;
    // Newton on the dependent dof (one step where g is linear in it; DIST is quadratic).
    for (int it = 0;; ++it) {
      const Real g = constraint_value(c, coords, u, &gradient);
      const Real step = g / gradient[0];
      if (!std::isfinite(step) || it == 20)
        throw SolverError(c.keyword + " at " + c.where.file + ":" + std::to_string(c.where.line) +
                          ": the constraint cannot be solved for " + describe(*model_, d) +
                          " in the current configuration (it no longer depends on that dof)");
      u[d] -= step;
      if (std::abs(step) <= 1e-14 * (1 + std::abs(coords(d / 3, d % 3)) + std::abs(u[d]))) break;
    }
    constraint_value(c, coords, u, &gradient);
    Real constant = u[d];
    DofTerm* terms = terms_.data() + start_[d];
    for (std::size_t k = 0; k < row.other_dofs.size(); ++k) {
      const Real coef = -gradient[static_cast<Index>(k + 1)] / gradient[0];
      terms[k].coef = coef;
      constant -= coef * u[row.other_dofs[k]];
    }
    row_constant_[d] = constant;
  }
  // Rows following the constraints, dependencies first: each the combination of its sources'
  // current rows (sums of the same unknown collected in the row's own merged terms).
  for (const FollowerRow& row : follower_rows_) {
    DofTerm* begin = terms_.data() + start_[row.dof];
    DofTerm* end = terms_.data() + start_[row.dof + 1];
    for (DofTerm* t = begin; t != end; ++t) t->coef = 0;
    Real constant = 0, value = 0;
    for (const auto& [source, c] : row.sources) {
      for (auto t = terms_begin(source); t != terms_end(source); ++t) {
        DofTerm* target = std::find_if(begin, end, [&](const DofTerm& m) {
          return m.index == t->index && m.is_prescribed == t->is_prescribed;
        });
        target->coef += c * t->coef;
      }
      constant += c * row_constant_[source];
      value += c * u[source];
    }
    row_constant_[row.dof] = constant;
    u[row.dof] = value;
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

VecX DofMap::expand(const VecX& x, const VecX& prescribed_values) const {
  VecX u = VecX::Zero(n_dofs());
  for (int d = 0; d < n_dofs(); ++d) {
    Real v = 0;
    for (auto t = terms_begin(d); t != terms_end(d); ++t)
      v += t->coef * (t->is_prescribed ? prescribed_values[t->index] : x[t->index]);
    u[d] = v;
  }
  if (!row_constant_.empty()) u += Eigen::Map<const VecX>(row_constant_.data(), n_dofs());
  return u;
}

void DofMap::add_constraint_forces(MatX3& nodal_forces) const {
  for (const NonlinearRow& row : nonlinear_rows_) {
    const Real f = nodal_forces(row.dof / 3, row.dof % 3);
    const DofTerm* terms = terms_.data() + start_[row.dof];
    for (std::size_t k = 0; k < row.other_dofs.size(); ++k)
      if (row.elementless[k])
        nodal_forces(row.other_dofs[k] / 3, row.other_dofs[k] % 3) += terms[k].coef * f;
  }
}

bool DofMap::same_structure(const DofMap& other) const {
  if (start_ != other.start_ || terms_.size() != other.terms_.size()) return false;
  if (moving_dof_ != other.moving_dof_) return false;
  for (int d = 0; d < n_dofs(); ++d)
    for (int k = start_[d]; k < start_[d + 1]; ++k)
      if (terms_[k].index != other.terms_[k].index ||
          terms_[k].is_prescribed != other.terms_[k].is_prescribed ||
          (!moving_dof_[d] && terms_[k].coef != other.terms_[k].coef))
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
