#include "inp/element_names.hpp"

#include <array>
#include <stdexcept>

#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {
using element::ElementType;

constexpr std::array<ElementName, 9> kElementNames{{
    {ElementType::C3D4, "C3D4", 4, 4},
    {ElementType::C3D6, "C3D6", 6, 5},
    {ElementType::C3D8, "C3D8", 8, 6},
    {ElementType::C3D8R, "C3D8R", 8, 6},
    {ElementType::C3D8I, "C3D8I", 8, 6},
    {ElementType::C3D10, "C3D10", 10, 4},
    {ElementType::C3D15, "C3D15", 15, 5},
    {ElementType::C3D20, "C3D20", 20, 6},
    {ElementType::C3D20R, "C3D20R", 20, 6},
}};
}  // namespace

std::optional<ElementName> find_element_name(std::string_view name) {
  const std::string upper = to_upper(name);
  for (const ElementName& entry : kElementNames) {
    if (entry.name == upper) return entry;
  }
  return std::nullopt;
}

const ElementName& element_name_of(element::ElementType type) {
  for (const ElementName& entry : kElementNames) {
    if (entry.type == type) return entry;
  }
  throw std::logic_error("element_name_of: type missing from the reader's table");
}

}  // namespace kontakt::inp
