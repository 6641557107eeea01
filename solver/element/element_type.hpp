// The solid element library: types, topology, faces and integration rules in ccx's conventions.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace kontakt::element {

enum class ElementType { C3D4, C3D6, C3D8, C3D8R, C3D8I, C3D10, C3D15, C3D20, C3D20R };

/// Fixed facts about one element type.
struct ElementTraits {
  ElementType type;
  std::string_view name;    ///< Abaqus/ccx name, upper case ("C3D20R")
  int n_nodes;              ///< nodes the deck gives (C3D8I: 8)
  int n_corner_nodes;
  int n_ip;                 ///< integration points, in ccx's output order
  int n_faces;              ///< faces S1..Sn
  bool is_quadratic;
};

const ElementTraits& traits(ElementType type);

/// Case-insensitive lookup of a deck name; nullopt when the name is not in our library.
std::optional<ElementType> element_type_from_name(std::string_view name);

/// Local node indices (0-based) of face `face` (1-based, ccx numbering S1..Sn), corners first,
/// then midside nodes, ordered so the right-hand normal points out of the element.
std::span<const int> face_nodes(ElementType type, int face);

}  // namespace kontakt::element
