#include "inp/element_names.hpp"

#include <array>
#include <stdexcept>

#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {
using element::ElementType;

using model::Planar;

constexpr std::array<ElementName, 27> kElementNames{{
    {ElementType::C3D4, "C3D4", 4, 4},
    {ElementType::C3D6, "C3D6", 6, 5},
    {ElementType::C3D8, "C3D8", 8, 6},
    {ElementType::C3D8R, "C3D8R", 8, 6},
    {ElementType::C3D8I, "C3D8I", 8, 6},
    {ElementType::C3D10, "C3D10", 10, 4},
    {ElementType::C3D15, "C3D15", 15, 5},
    {ElementType::C3D20, "C3D20", 20, 6},
    {ElementType::C3D20R, "C3D20R", 20, 6},
    // 2D elements: the 3D type of ccx's expansion (linear quads with full integration stay
    // C3D8, not C3D8I), the 2D node count, the edges as faces.
    {ElementType::C3D6, "CPS3", 3, 3, Planar::PlaneStress},
    {ElementType::C3D8, "CPS4", 4, 4, Planar::PlaneStress},
    {ElementType::C3D8R, "CPS4R", 4, 4, Planar::PlaneStress},
    {ElementType::C3D15, "CPS6", 6, 3, Planar::PlaneStress},
    {ElementType::C3D20, "CPS8", 8, 4, Planar::PlaneStress},
    {ElementType::C3D20R, "CPS8R", 8, 4, Planar::PlaneStress},
    {ElementType::C3D6, "CPE3", 3, 3, Planar::PlaneStrain},
    {ElementType::C3D8, "CPE4", 4, 4, Planar::PlaneStrain},
    {ElementType::C3D8R, "CPE4R", 4, 4, Planar::PlaneStrain},
    {ElementType::C3D15, "CPE6", 6, 3, Planar::PlaneStrain},
    {ElementType::C3D20, "CPE8", 8, 4, Planar::PlaneStrain},
    {ElementType::C3D20R, "CPE8R", 8, 4, Planar::PlaneStrain},
    {ElementType::C3D6, "CAX3", 3, 3, Planar::Axisymmetric},
    {ElementType::C3D8, "CAX4", 4, 4, Planar::Axisymmetric},
    {ElementType::C3D8R, "CAX4R", 4, 4, Planar::Axisymmetric},
    {ElementType::C3D15, "CAX6", 6, 3, Planar::Axisymmetric},
    {ElementType::C3D20, "CAX8", 8, 4, Planar::Axisymmetric},
    {ElementType::C3D20R, "CAX8R", 8, 4, Planar::Axisymmetric},
}};
}  // namespace

std::optional<ElementName> find_element_name(std::string_view name) {
  const std::string upper = to_upper(name);
  for (const ElementName& entry : kElementNames) {
    if (entry.name == upper) return entry;
  }
  return std::nullopt;
}

const ElementName& element_name_of(element::ElementType type, model::Planar planar) {
  for (const ElementName& entry : kElementNames) {
    if (entry.type == type && entry.planar == planar) return entry;
  }
  throw std::logic_error("element_name_of: type missing from the reader's table");
}

}  // namespace kontakt::inp
