// One converged output state of the model: what the writers (.dat, HDF5) consume.
#pragma once

#include <limits>

#include <optional>
#include <vector>

#include "core/types.hpp"

namespace kontakt::output {

/// One contact point of the converged state: a surface-to-surface integration point or a
/// node-to-surface slave node. *CONTACT PRINT rows (CDIS, CSTR, CELS) list the active ones.
struct ContactPointRecord {
  int pair = 0;              ///< index into Model::contact_pairs
  int slave_element = -1;    ///< internal element index of the slave face (-1: nodal slave)
  int slave_face = 0;        ///< 1-based ccx face number of that element
  int slave_node = -1;       ///< node-to-surface: internal index of the slave node
  Vec2 xi = Vec2::Zero();    ///< local coordinates in the slave face
  Vec3 x = Vec3::Zero();     ///< current position of the point
  bool active = false;       ///< carries force in the converged state
  /// Active and inside the Coulomb cone (friction or TIED); frictionless points slide.
  bool sticking = false;
  Real clearance = 0;        ///< g = -overclosure: negative when penetrating (ccx's COPEN sign)
  Real pressure = 0;         ///< positive in compression (TIED may be negative)
  Vec2 slip = Vec2::Zero();  ///< tangential relative displacement along t1, t2 (CSLIP1/2)
  Vec2 shear = Vec2::Zero(); ///< shear stress along t1, t2 (CSHEAR1/2)
  Real area = 0;             ///< slave area the point represents
  Real energy = 0;           ///< spring energy (CELS)
};

/// Contact variables at the nodes: extrapolated from the points per slave face (thesis
/// §4.3.3) and averaged over the faces at a node; zero away from the slave surfaces.
struct ContactNodal {
  VecX CPRESS, COPEN;        ///< n_nodes
  MatX CSHEAR, CSLIP;        ///< n_nodes x 2
  VecX status;               ///< CSTATUS: 0 open, 1 stick, 2 slip (as ccx; not the member
                             ///< name CSTATUS, a macro of <sys/ttydefaults.h>)
};

struct Frame {
  int step = 1;             ///< 1-based
  int increment = 1;        ///< 1-based within the step
  Real step_time = 0;
  Real total_time = 0;      ///< accumulated over steps; the time ccx prints in .dat headers
  bool converged = true;
  bool is_step_end = true;  ///< last increment of its step (prints are always written then)
  /// Engaged when the step's output follows *TIME POINTS instead of FREQUENCY=: whether this
  /// increment ended on one of them.
  std::optional<bool> at_time_point;

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
  /// PEEQ extrapolated and averaged the same way; empty when PEEQ is.
  VecX PEEQ_nodal;
  /// One row per Model::connectors entry: what a T3D2 truss prints at each of the 8 points of
  /// ccx's expanded element (analysis/truss; rows of springs and gaps stay zero). Empty for a
  /// model without trusses. The HDF5 and .frd files leave trusses out, as all connectors.
  MatX6 truss_S, truss_E;
  VecX truss_ENER;
  /// Nodal temperatures at the frame's time (n_nodes); empty for a model without temperatures.
  VecX T;
  /// Per element: 0 for one *MODEL CHANGE removed (the .dat prints no rows for it, as ccx);
  /// empty: all elements are in the model.
  std::vector<char> element_active;

  /// Contact state; both empty for models without contact pairs.
  std::vector<ContactPointRecord> contact_points;
  ContactNodal contact_nodal;
  int n_active_contact = 0;  ///< active contact elements (points or nodes)
};

/// One record per attempted increment, as in ccx's .sta/.cvg and the HDF5 /history group.
struct IncrementRecord {
  int step = 1, increment = 1, attempts = 1, iterations = 1;
  Real total_time = 0, step_time = 0, dt = 0;
  bool converged = true;
  /// Models with contact, converged increments: the energy the contact stabilisation absorbed
  /// and the strain energy at the increment's end; NaN otherwise.
  Real stabilisation_energy = std::numeric_limits<Real>::quiet_NaN();
  Real strain_energy = std::numeric_limits<Real>::quiet_NaN();
};

}  // namespace kontakt::output
