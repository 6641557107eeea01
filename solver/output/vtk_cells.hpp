// Element type -> VTK / XDMF cell type and the node permutation from ccx (Abaqus) order to VTK
// order. Kept here so the writers do not depend on the element library's implementation.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "element/element_type.hpp"

namespace kontakt::output {

struct VtkCell {
  element::ElementType type;
  std::string_view name;      ///< "C3D20R"
  int n_nodes;
  std::uint8_t vtk_type;      ///< VTK_TETRA 10, VTK_QUADRATIC_TETRA 24, VTK_HEXAHEDRON 12,
                              ///< VTK_QUADRATIC_HEXAHEDRON 25, VTK_WEDGE 13, VTK_QUADRATIC_WEDGE 26
  int xdmf_type;              ///< Tetrahedron 6, Tetrahedron_10 38, Hexahedron 9,
                              ///< Hexahedron_20 48, Wedge 8, Wedge_15 40
  /// vtk_node[i] = ccx_node[perm[i]] (0-based local indices).
  std::span<const int> perm;
};

const VtkCell& vtk_cell(element::ElementType type);

}  // namespace kontakt::output
