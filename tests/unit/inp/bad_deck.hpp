// Malformed decks and what the InputError for each must say; run by test_errors.cpp.
#pragma once

#include <string>
#include <vector>

namespace kontakt::inp::test {

struct BadDeck {
  const char* name;
  std::string deck;
  int line;              ///< expected line in bad.inp
  std::string keyword;   ///< expected keyword
  std::string fragment;  ///< expected part of the message
};

/// The contact keywords' cases (test_contact_errors.cpp).
std::vector<BadDeck> contact_bad_decks();

/// The *TIE cases (test_tie.cpp).
std::vector<BadDeck> tie_bad_decks();

/// The *TRANSFORM cases (test_transform.cpp).
std::vector<BadDeck> transform_bad_decks();

/// The *DISTRIBUTING COUPLING cases (test_coupling.cpp).
std::vector<BadDeck> coupling_bad_decks();

/// The SPRINGA, GAPUNI, *SPRING and *GAP cases (test_connector.cpp).
std::vector<BadDeck> connector_bad_decks();

/// The T3D2 truss cases (test_truss.cpp).
std::vector<BadDeck> truss_bad_decks();

/// The *RIGID BODY and *MPC cases (test_nonlinear_constraint.cpp).
std::vector<BadDeck> nonlinear_constraint_bad_decks();

/// The *PRE-TENSION SECTION cases (test_pretension.cpp).
std::vector<BadDeck> pretension_bad_decks();

/// The material cards' cases (test_material.cpp).
std::vector<BadDeck> material_bad_decks();
/// The plane stress / strain / axisymmetric cases (test_plane_elements.cpp).
std::vector<BadDeck> plane_bad_decks();
/// The step set-up cards' cases (test_step_setup.cpp).
std::vector<BadDeck> step_setup_bad_decks();

}  // namespace kontakt::inp::test
