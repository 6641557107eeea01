// One converged output state of the model: what the writers (.dat, HDF5) consume.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace kontakt::output {

struct Frame {
  int step = 1;             ///< 1-based
  int increment = 1;        ///< 1-based within the step
  Real step_time = 0;
  Real total_time = 0;      ///< accumulated over steps; the time ccx prints in .dat headers
  bool converged = true;
  bool is_step_end = true;  ///< last increment of its step (prints are always written then)

  MatX3 U;                  ///< n_nodes x 3 displacements
  MatX3 RF;                 ///< n_nodes x 3 internal nodal forces summed over elements
  /// Integration point data of all elements, concatenated: element e owns rows
  /// ip_offset[e] .. ip_offset[e+1]-1, in ccx's point order.
  std::vector<Index> ip_offset;
  MatX6 S;                  ///< Cauchy stress
  MatX6 E;                  ///< total strain
  VecX ENER;                ///< strain energy density per point
  VecX ip_volume;           ///< volume carried by each point (for EVOL, ELSE totals)
  VecX EVOL;                ///< per element volume
  /// Equivalent plastic strain per point; empty for purely elastic models (then ccx prints
  /// no PEEQ block and the HDF5 file gets no PEEQ array).
  VecX PEEQ;
  /// Nodal values extrapolated from the points and averaged over the elements at each node.
  MatX6 S_nodal, E_nodal;
};

/// One record per attempted increment, as in ccx's .sta/.cvg and the HDF5 /history group.
struct IncrementRecord {
  int step = 1, increment = 1, attempts = 1, iterations = 1;
  Real total_time = 0, step_time = 0, dt = 0;
  bool converged = true;
};

}  // namespace kontakt::output
