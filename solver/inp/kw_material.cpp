// *MATERIAL, *ELASTIC, *DENSITY, *EXPANSION, *SOLID SECTION.
#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

model::Material& current_material(const Record& record, DeckState& state) {
  if (state.current_material < 0) fail(record, "must follow a *MATERIAL card");
  return state.model.materials[static_cast<std::size_t>(state.current_material)];
}

/// Material constants with an optional trailing temperature column. Several lines would be
/// a temperature table, which we do not support.
const DataLine& single_constant_line(const Record& record, std::size_t n_values) {
  if (record.lines.empty()) fail(record, "data line missing");
  if (record.lines.size() > 1) {
    fail(record, record.lines[1], "temperature-dependent material data is not supported");
  }
  const DataLine& line = record.lines.front();
  require_field_count(record, line, n_values, n_values + 1);
  if (line.fields.size() > n_values) (void)real_field(record, line, n_values);  // temperature
  return line;
}

}  // namespace

void handle_material(const Record& record, DeckState& state) {
  check_params(record, {"NAME"});
  const std::string name = remove_blanks(to_upper(required_value(record, "NAME")));
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  if (state.material_index.contains(name)) fail(record, "material " + name + " defined twice");
  state.current_material = static_cast<int>(state.model.materials.size());
  state.material_index[name] = state.current_material;
  model::Material material;
  material.name = name;
  material.where = record.where;
  state.model.materials.push_back(std::move(material));
}

void handle_elastic(const Record& record, DeckState& state) {
  check_params(record, {"TYPE"});
  const std::string type = name_value(record, "TYPE").value_or("ISO");
  if (type != "ISO" && type != "ISOTROPIC") {
    fail(record, "TYPE=" + type + " is not supported (only TYPE=ISO)");
  }
  model::Material& material = current_material(record, state);
  const DataLine& line = single_constant_line(record, 2);
  material.young = real_field(record, line, 0);
  material.poisson = real_field(record, line, 1);
  if (material.young <= 0) fail(record, line, "Young's modulus must be positive");
  if (material.poisson <= -1 || material.poisson >= 0.5) {
    fail(record, line, "Poisson's ratio must lie in (-1, 0.5)");
  }
}

void handle_plastic(const Record& record, DeckState& state) {
  check_params(record, {"HARDENING"});
  const std::string hardening = to_upper(name_value(record, "HARDENING").value_or("ISOTROPIC"));
  if (hardening != "ISOTROPIC")
    fail(record, "HARDENING=" + hardening + " is not supported yet (only ISOTROPIC)");
  model::Material& material = current_material(record, state);
  require_line_count(record, 1, 10000);
  std::optional<Real> temperature;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 3);
    require_one_temperature(record, line, 2, temperature, "temperature-dependent hardening");
    const Real stress = real_field(record, line, 0), strain = real_field(record, line, 1);
    if (!(stress >= 0)) fail(record, line, "the yield stress must not be negative");
    if (material.plastic.empty() ? strain != 0 : !(strain > material.plastic.back().second))
      fail(record, line, material.plastic.empty()
                             ? "the first row must be at zero plastic strain (initial yield)"
                             : "plastic strains must increase from row to row");
    // The return mapping needs 3G + H > 0: a curve that softens faster has no unique answer.
    if (!material.plastic.empty() && material.young > 0) {
      const auto [s0, e0] = material.plastic.back();
      const Real shear = material.young / (2 * (1 + material.poisson));
      if (!((stress - s0) / (strain - e0) > -3 * shear))
        fail(record, line, "the curve softens faster than -3G (G the shear modulus of *ELASTIC)");
    }
    material.plastic.emplace_back(stress, strain);
  }
}

void handle_density(const Record& record, DeckState& state) {
  check_params(record, {});
  model::Material& material = current_material(record, state);
  const DataLine& line = single_constant_line(record, 1);
  material.density = real_field(record, line, 0);
  if (*material.density <= 0) fail(record, line, "density must be positive");
}

void handle_expansion(const Record& record, DeckState& state) {
  check_params(record, {"TYPE", "ZERO"});
  const std::string type = name_value(record, "TYPE").value_or("ISO");
  if (type != "ISO") fail(record, "TYPE=" + type + " is not supported (only TYPE=ISO)");
  model::Material& material = current_material(record, state);
  if (const Param* zero = find_param(record, "ZERO")) {
    const std::optional<Real> value = parse_real(zero->value);
    if (!value) fail(record, "ZERO=" + zero->value + " is not a number");
    material.expansion_zero = *value;
  }
  const DataLine& line = single_constant_line(record, 1);
  material.expansion = real_field(record, line, 0);
}

void handle_solid_section(const Record& record, DeckState& state) {
  if (has_param(record, "ORIENTATION")) fail(record, "ORIENTATION= is not supported");
  check_params(record, {"ELSET", "MATERIAL", "OFFSET"});
  // OFFSET= moves plane elements' layer off the z = 0 plane, in thicknesses (ccx).
  Real offset = 0;
  if (const auto* param = find_param(record, "OFFSET")) {
    const std::optional<Real> value = parse_real(param->value);
    if (!value) fail(record, "OFFSET=" + param->value + " is not a number");
    offset = *value;
  }
  // The data line's first field is the thickness of plane stress / strain elements (ccx: a
  // value <= 0 or none means 1); solids and axisymmetric elements do not use it.
  if (record.lines.size() > 1) fail(record, record.lines[1], "unexpected data line");
  Real thickness = 1;
  if (!record.lines.empty() && !record.lines.front().fields.empty()) {
    const Real given = real_field_or(record, record.lines.front(), 0, 0);
    if (given > 0) thickness = given;
  }
  const std::string elset = remove_blanks(to_upper(required_value(record, "ELSET")));
  const std::string material = remove_blanks(to_upper(required_value(record, "MATERIAL")));
  state.sections.push_back(RawSection{elset, material, record.where, thickness, offset});
}

}  // namespace kontakt::inp
