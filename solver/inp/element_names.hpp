// The solid element names the reader accepts, with the counts it needs for validation.
// Kept local to the reader so kontakt_inp does not depend on the element library's sources.
#pragma once

#include <optional>
#include <string_view>

#include "element/element_type.hpp"

namespace kontakt::inp {

struct ElementName {
  element::ElementType type;
  std::string_view name;  ///< upper case, as in the deck
  int n_nodes;            ///< node numbers the deck must give (C3D8I: 8)
  int n_faces;            ///< faces S1..Sn / P1..Pn
};

/// Case-insensitive lookup; nullopt when the type is not in our library.
std::optional<ElementName> find_element_name(std::string_view name);

/// The entry for a type already known to be supported.
const ElementName& element_name_of(element::ElementType type);

}  // namespace kontakt::inp
