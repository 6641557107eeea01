// Small hand-written decks shared by the reader tests.
#pragma once

#include <string>

namespace kontakt::inp::test {

/// Two C3D8 cubes side by side (nodes 1..12), a material, a section; no step.
inline std::string two_cubes_model() {
  return R"(*HEADING
Two cubes
*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 2, 0, 0
10, 2, 1, 0
11, 2, 0, 1
12, 2, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 2, 9, 10, 3, 6, 11, 12, 7
*NSET, NSET=FIX
1, 4, 5, 8
*NSET, NSET=TIP
9, 10, 11, 12
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
)";
}

/// The two cubes with contact surfaces on the faces they share (x = 1): MASTER = element 1
/// face S4, SLAVE = element 2 face S6, SLAVENODES = nodes 6, 7. Lines 27..32; what follows
/// starts at line 33.
inline std::string two_cubes_surfaces() {
  return two_cubes_model() + R"(*SURFACE, NAME=MASTER
1, S4
*SURFACE, NAME=SLAVE
2, S6
*SURFACE, NAME=SLAVENODES, TYPE=NODE
6, 7
)";
}

/// A linear surface interaction SI (K = 1e7) on three lines.
inline std::string linear_interaction() {
  return "*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e7\n";
}

/// A minimal one-step static analysis on the two cubes.
inline std::string two_cubes_static() {
  return two_cubes_model() + R"(*BOUNDARY
FIX, 1, 3
*STEP
*STATIC
*CLOAD
TIP, 1, 10.
*NODE PRINT, NSET=TIP
U
*END STEP
)";
}

}  // namespace kontakt::inp::test
