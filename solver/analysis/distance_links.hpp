// *MPC DIST as ccx 2.20 applies it: the distance between two nodes may not exceed d. The
// constraint is in force only while the nodes are linked, and the link changes at most once
// per increment, at its start, judged on the converged state before it: free -> linked when
// the distance has reached d, linked -> free when the constraint pushes the nodes apart. So a
// free pair may overshoot d for one increment and a linked one push for one (ccx's dist: 7.2025
// at t = 0.6, linked from 0.7; pushing at 1.5, free from 1.6; measured).
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

class DistanceLinks {
 public:
  /// Every DIST free; one whose nodes are farther apart than d already links at the first
  /// increment.
  explicit DistanceLinks(const model::Model& model);

  bool empty() const { return links_.empty(); }
  /// Per Model::nonlinear_constraints: in force in the current increment (DofMap's `in_force`).
  const std::vector<char>& in_force() const { return in_force_; }

  /// The increment's links from the committed state: what changed against the previous
  /// attempt's, a line per DIST (the constraint layout must then be rebuilt; ccx prints "switch
  /// to linked" / "switch to free"). A redone increment decides alike and reports nothing.
  std::vector<std::string> begin_increment();
  /// The increment converged at `u` with `residual` (internal minus external nodal forces:
  /// at a linked DIST's dependent dof, the force it exerts there): its links are committed,
  /// and what the next increment will decide is judged there.
  void commit(const VecX& u, const VecX& residual);

 private:
  struct Link {
    std::size_t constraint = 0;  ///< into Model::nonlinear_constraints
    bool linked = false;         ///< committed
    bool switch_next = false;    ///< at the next increment's start
  };
  /// Judges whether the committed state of `link` calls for a switch.
  bool calls_for_switch(const Link& link, const VecX& u, const VecX& residual) const;

  const model::Model& model_;
  std::vector<Link> links_;
  std::vector<char> in_force_;
};

}  // namespace kontakt::analysis
