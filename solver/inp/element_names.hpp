// The element names the reader accepts, with the counts it needs for validation: the solids
// and the plane stress / plane strain / axisymmetric elements, read as the 3D type ccx expands
// them into (model/plane_expansion).
// Kept local to the reader so kontakt_inp does not depend on the element library's sources.
#pragma once

#include <optional>
#include <string_view>

#include "element/element_type.hpp"
#include "model/model.hpp"

namespace kontakt::inp {

struct ElementName {
  element::ElementType type;
  std::string_view name;  ///< upper case, as in the deck
  int n_nodes;            ///< node numbers the deck must give (C3D8I: 8; CPE8: 8)
  int n_faces;            ///< faces S1..Sn / P1..Pn (2D elements: their edges)
  model::Planar planar = model::Planar::None;
};

/// Case-insensitive lookup; nullopt when the type is not in our library.
std::optional<ElementName> find_element_name(std::string_view name);

/// The entry of an element already read.
const ElementName& element_name_of(element::ElementType type,
                                   model::Planar planar = model::Planar::None);

}  // namespace kontakt::inp
