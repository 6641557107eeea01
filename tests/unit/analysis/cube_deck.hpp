// The unit-cube decks the driver tests share: one C3D8 element, node sets X0 and X1 for the
// faces x = 0 and x = 1, and symmetry rollers that leave the cube free to stretch sideways.
#pragma once

#include <string>

namespace kontakt::testing_decks {

/// Nodes, element, sets, a material named M with `material_lines` and its section.
inline std::string cube_model(const std::string& material_lines) {
  return R"(*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=X0
1, 4, 5, 8
*NSET, NSET=X1
2, 3, 6, 7
*MATERIAL, NAME=M
)" + material_lines + "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n";
}

/// x fixed on x = 0, plus the least y and z supports that stop rigid motion.
inline const char* kRollers = R"(*BOUNDARY
X0, 1
1, 2, 3
2, 2, 3
4, 3
5, 2
)";

}  // namespace kontakt::testing_decks
