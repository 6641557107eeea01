// *MATERIAL, *ELASTIC, *HYPERELASTIC, *HYPERFOAM, *DENSITY, *EXPANSION, *SOLID SECTION,
// *MEMBRANE, *ORIENTATION.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "material/anisotropic_elastic.hpp"
#include "material/hyperelastic_potential.hpp"

#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

model::Material& current_material(const Record& record, DeckState& state) {
  if (state.current_material < 0) fail(record, "must follow a *MATERIAL card");
  return state.model.materials[static_cast<std::size_t>(state.current_material)];
}

/// N constants per data line and an optional temperature column (empty or missing: 0), one
/// line per temperature, temperatures strictly ascending (ccx interpolates between them).
/// `check` validates each row's constants (it fails on the line).
template <std::size_t N, class Check>
material::TemperatureTable<N> temperature_table(const Record& record, Check check) {
  if (record.lines.empty()) fail(record, "data line missing");
  material::TemperatureTable<N> table;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, N, N + 1);
    typename material::TemperatureTable<N>::Row row;
    for (std::size_t i = 0; i < N; ++i) row[i] = real_field(record, line, i);
    const Real temperature = real_field_or(record, line, N, 0);
    if (!table.empty() && !(temperature > table.temperatures.back()))
      fail(record, line, "temperatures must increase from line to line (a table by temperature)");
    check(line, row);
    table.add(temperature, row);
  }
  return table;
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

namespace {

/// The constants of the orthotropic and anisotropic types: sets of `n_lines` data lines (8
/// constants on every line but the last, which ends with the optional temperature), N constants
/// per set, one set per temperature; each set converted to the 21 ANISO constants by `convert`
/// (which throws std::invalid_argument for bad constants) and required positive definite.
template <std::size_t N, class Convert>
material::TemperatureTable<21> anisotropic_table(const Record& record, std::size_t n_lines,
                                                 Convert convert) {
  if (record.lines.empty()) fail(record, "data line missing");
  if (record.lines.size() % n_lines != 0)
    fail(record, record.lines.back(),
         std::to_string(N) + " constants take " + std::to_string(n_lines) +
             " data lines per temperature (8 a line, the temperature after the last)");
  material::TemperatureTable<21> table;
  for (std::size_t first = 0; first < record.lines.size(); first += n_lines) {
    std::array<Real, N> constants{};
    std::size_t k = 0;
    for (std::size_t l = 0; l < n_lines; ++l) {
      const DataLine& line = record.lines[first + l];
      const std::size_t on_line = l + 1 < n_lines ? 8 : N - 8 * (n_lines - 1);
      require_field_count(record, line, on_line, l + 1 < n_lines ? on_line : on_line + 1);
      for (std::size_t i = 0; i < on_line; ++i) constants[k++] = real_field(record, line, i);
    }
    const DataLine& last = record.lines[first + n_lines - 1];
    const Real temperature = real_field_or(record, last, N - 8 * (n_lines - 1), 0);
    if (!table.empty() && !(temperature > table.temperatures.back()))
      fail(record, last, "temperatures must increase from set to set (a table by temperature)");
    material::AnisotropicConstants d{};
    try {
      d = convert(constants);
    } catch (const std::invalid_argument& e) {
      fail(record, last, e.what());
    }
    if (!material::is_positive_definite(material::anisotropic_stiffness(d)))
      fail(record, last, "the elasticity matrix is not positive definite");
    table.add(temperature, d);
  }
  return table;
}

}  // namespace

void handle_elastic(const Record& record, DeckState& state) {
  check_params(record, {"TYPE"});
  // ccx compares the first characters of the value: ORTHO(TROPIC), ANISO(TROPIC), ...
  const std::string type = name_value(record, "TYPE").value_or("ISO");
  model::Material& material = current_material(record, state);
  material.elastic = {};
  material.anisotropic = {};
  if (type.starts_with("ISO")) {
    material.elastic = temperature_table<2>(record, [&](const DataLine& line, const auto& row) {
      if (!(row[0] > 0)) fail(record, line, "Young's modulus must be positive");
      if (!(row[1] > -1 && row[1] < 0.5))
        fail(record, line, "Poisson's ratio must lie in (-1, 0.5)");
    });
  } else if (type.starts_with("ORTHO")) {
    material.anisotropic = anisotropic_table<9>(record, 2, material::from_orthotropic);
  } else if (type.starts_with("ENGINEERINGCONSTANTS")) {
    material.anisotropic = anisotropic_table<9>(record, 2, material::from_engineering);
  } else if (type.starts_with("ANISO")) {
    material.anisotropic =
        anisotropic_table<21>(record, 3, [](const material::AnisotropicConstants& d) { return d; });
  } else {
    fail(record, "TYPE=" + type + ": expected ISO, ORTHO, ENGINEERING CONSTANTS or ANISO");
  }
}

namespace {

/// The n constants of *HYPERELASTIC / *HYPERFOAM in ccx's layout: 8 a line, the temperature
/// after the last; one temperature only.
std::vector<Real> hyperelastic_constants(const Record& record, std::size_t n) {
  if (record.lines.empty()) fail(record, "data line missing");
  std::vector<Real> values;
  for (const DataLine& line : record.lines)
    for (std::size_t i = 0; i < line.fields.size(); ++i)
      values.push_back(real_field_or(record, line, i, 0));
  if (values.size() < n || values.size() > n + 1 || record.lines.size() != (n + 8) / 8)
    fail(record, record.lines.back(),
         std::to_string(n) + " constants expected (8 a line), then the temperature: one "
                             "temperature only (no table)");
  values.resize(n);
  return values;
}

/// The data line holding constant k (0-based) of hyperelastic_constants, and its field there.
const DataLine& constant_line(const Record& record, std::size_t k) { return record.lines[k / 8]; }
std::string constant_field(std::size_t k) { return "field " + std::to_string(k % 8 + 1); }

/// The compressibility ccx takes for a D_k given as 0 (manual, "Hyperelastic and hyperfoam
/// materials": an initial Poisson ratio of 0.475), measured with ccx 2.20 on single-element
/// decks for OGDEN N = 1..3, NEO HOOKE, MOONEY-RIVLIN, POLYNOMIAL and REDUCED POLYNOMIAL N = 2:
/// D_k = (0.1 / mu)^k with mu the shear modulus at rest (D1 alone: a bulk modulus of 20 mu).
Real default_compressibility(Real shear_modulus, std::size_t k) {
  return std::pow(0.1 / shear_modulus, static_cast<Real>(k));
}

/// D_1..D_n from values[first..]: not negative, a 0 taking ccx's default for `shear_modulus`.
void read_compressibilities(const Record& record, const std::vector<Real>& values,
                            std::size_t first, std::size_t n, Real shear_modulus,
                            std::array<Real, 3>& d) {
  for (std::size_t k = 0; k < n; ++k) {
    d[k] = values[first + k];
    if (d[k] < 0)
      fail(record, constant_line(record, first + k),
           "D" + std::to_string(k + 1) + " (" + constant_field(first + k) +
               ") must not be negative");
    if (d[k] == 0) d[k] = default_compressibility(shear_modulus, k + 1);
  }
}

/// The N (mu_i, alpha_i) pairs leading OGDEN's and HYPERFOAM's constants: alpha_i nonzero and
/// the shear modulus at rest, sum mu_i, positive. Returns that modulus.
template <class Potential>
Real read_stretch_terms(const Record& record, const std::vector<Real>& values, int n,
                        Potential& p) {
  p.n_terms = n;
  Real shear_modulus = 0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    p.mu[i] = values[2 * i];
    p.alpha[i] = values[2 * i + 1];
    if (p.alpha[i] == 0)
      fail(record, constant_line(record, 2 * i + 1),
           "alpha" + std::to_string(i + 1) + " (" + constant_field(2 * i + 1) +
               ") must not be zero");
    shear_modulus += p.mu[i];
  }
  if (!(shear_modulus > 0))
    fail(record, record.lines.front(),
         "the sum of the mu_i (the shear modulus at rest) must be positive");
  return shear_modulus;
}

/// OGDEN: mu_1, alpha_1, ..., mu_N, alpha_N, D_1, ..., D_N.
material::Ogden read_ogden(const Record& record, int n) {
  const std::size_t n_terms = static_cast<std::size_t>(n);
  const std::vector<Real> values = hyperelastic_constants(record, 3 * n_terms);
  material::Ogden p;
  const Real shear_modulus = read_stretch_terms(record, values, n, p);
  read_compressibilities(record, values, 2 * n_terms, n_terms, shear_modulus, p.d);
  return p;
}

void set_potential(const Record& record, DeckState& state,
                   const material::HyperelasticPotential& potential) {
  model::Material& material = current_material(record, state);
  if (material.hyperelastic)
    fail(record, "material " + material.name + " has a *HYPERELASTIC or *HYPERFOAM potential "
                                               "already");
  material.hyperelastic = potential;
}

}  // namespace

void handle_hyperelastic(const Record& record, DeckState& state) {
  // The model is a parameter without value (ccx's default: POLYNOMIAL, N=1).
  check_params(record, {"NEOHOOKE", "MOONEY-RIVLIN", "POLYNOMIAL", "REDUCEDPOLYNOMIAL", "YEOH",
                        "OGDEN", "N"});
  const bool neo_hooke = has_param(record, "NEOHOOKE"), mooney = has_param(record, "MOONEY-RIVLIN");
  const bool reduced = has_param(record, "REDUCEDPOLYNOMIAL") || has_param(record, "YEOH");
  const bool ogden = has_param(record, "OGDEN");
  if (neo_hooke + mooney + reduced + ogden + has_param(record, "POLYNOMIAL") > 1)
    fail(record, "more than one model given");
  int n = int_param(record, "N").value_or(1);
  if (has_param(record, "YEOH")) n = 3;
  if ((neo_hooke || mooney) && n != 1) fail(record, "N=" + std::to_string(n) + ": this model has N=1");
  if (n < 1 || n > 3) fail(record, "N=" + std::to_string(n) + ": expected 1, 2 or 3");
  if (ogden) {
    set_potential(record, state, read_ogden(record, n));
    return;
  }
  // The constants in ccx's order: the C_ij by order (i descending within an order; only C_i0
  // for the reduced forms), then D_1..D_N.
  std::vector<std::pair<int, int>> c_terms;
  for (int order = 1; order <= n; ++order)
    for (int i = order; i >= 0; --i)
      if (!(reduced || neo_hooke) || i == order) c_terms.emplace_back(i, order - i);
  if (neo_hooke) c_terms = {{1, 0}};
  const std::vector<Real> values =
      hyperelastic_constants(record, c_terms.size() + static_cast<std::size_t>(n));
  material::HyperelasticPolynomial p;
  for (std::size_t k = 0; k < c_terms.size(); ++k)
    p.c[static_cast<std::size_t>(c_terms[k].first)][static_cast<std::size_t>(c_terms[k].second)] =
        values[k];
  // Stable at rest: shear modulus 2 (C10 + C01) > 0.
  if (!(p.c[1][0] + p.c[0][1] > 0))
    fail(record, record.lines.front(), "C10 + C01 (half the shear modulus) must be positive");
  read_compressibilities(record, values, c_terms.size(), static_cast<std::size_t>(n),
                         2 * (p.c[1][0] + p.c[0][1]), p.d);
  set_potential(record, state, p);
}

/// mu_1, alpha_1, ..., mu_N, alpha_N, nu_1, ..., nu_N; beta_i = nu_i / (1 - 2 nu_i).
void handle_hyperfoam(const Record& record, DeckState& state) {
  check_params(record, {"N"});
  const int n = int_param(record, "N").value_or(1);
  if (n < 1 || n > 3) fail(record, "N=" + std::to_string(n) + ": expected 1, 2 or 3");
  const std::size_t n_terms = static_cast<std::size_t>(n);
  const std::vector<Real> values = hyperelastic_constants(record, 3 * n_terms);
  material::Hyperfoam p;
  read_stretch_terms(record, values, n, p);
  for (std::size_t k = 0; k < n_terms; ++k) {
    const Real nu = values[2 * n_terms + k];
    // nu -> 1/2: beta and the bulk modulus grow without bound; nu <= -1: no positive bulk modulus.
    if (!(nu > -1 && nu < 0.5))
      fail(record, constant_line(record, 2 * n_terms + k),
           "nu" + std::to_string(k + 1) + " (" + constant_field(2 * n_terms + k) +
               ") must lie between -1 and 0.5");
    p.beta[k] = nu / (1 - 2 * nu);
  }
  set_potential(record, state, p);
}

/// E, nu, sigma0, n, alpha[, temperature]: one temperature only.
void handle_deformation_plasticity(const Record& record, DeckState& state) {
  check_params(record, {});
  require_line_count(record, 1, 100000);
  if (record.lines.size() > 1)
    fail(record, record.lines[1], "one temperature only: temperature tables are not supported");
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 5, 6);
  material::RambergOsgood law;
  law.young = real_field(record, line, 0);
  law.poisson = real_field(record, line, 1);
  law.yield = real_field(record, line, 2);
  law.exponent = real_field(record, line, 3);
  law.alpha = real_field(record, line, 4);
  if (!(law.young > 0)) fail(record, line, "E (field 1) must be positive");
  if (!(law.poisson > -1 && law.poisson < 0.5))
    fail(record, line, "Poisson's ratio (field 2) must lie between -1 and 0.5");
  if (!(law.yield > 0)) fail(record, line, "the yield stress sigma0 (field 3) must be positive");
  if (!(law.exponent >= 1)) fail(record, line, "the exponent n (field 4) must be at least 1");
  if (!(law.alpha >= 0)) fail(record, line, "alpha (field 5) must not be negative");
  current_material(record, state).deformation_plasticity = law;
}

namespace {

/// The (stress, plastic strain[, temperature]) lines of *PLASTIC or *CYCLIC HARDENING: one
/// curve per temperature, its lines together.
material::HardeningCurves read_hardening_curves(const Record& record,
                                                const model::Material& material) {
  require_line_count(record, 1, 10000);
  material::HardeningCurves curves;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 3);
    const Real stress = real_field(record, line, 0), strain = real_field(record, line, 1);
    const Real temperature = real_field_or(record, line, 2, 0);
    if (!(stress >= 0)) fail(record, line, "the yield stress must not be negative");
    const bool new_curve = curves.empty() || temperature != curves.temperatures.back();
    if (new_curve && !curves.empty() && !(temperature > curves.temperatures.back()))
      fail(record, line, "temperatures must increase from curve to curve (one curve per "
                         "temperature, its lines together)");
    if (new_curve ? strain != 0 : !(strain > curves.curves.back().points.back().second))
      fail(record, line, new_curve
                             ? "the first row of a curve must be at zero plastic strain (initial "
                               "yield)"
                             : "plastic strains must increase from row to row");
    if (new_curve) {
      curves.temperatures.push_back(temperature);
      curves.curves.emplace_back();
    }
    std::vector<std::pair<Real, Real>>& points = curves.curves.back().points;
    // The return mapping needs 3G + H > 0: a curve that softens faster has no unique answer
    // (G the smallest shear modulus of a temperature table).
    if (!points.empty() && !material.elastic.empty()) {
      const auto [s0, e0] = points.back();
      Real shear = std::numeric_limits<Real>::infinity();
      for (const auto& [young, poisson] : material.elastic.rows)
        shear = std::min(shear, young / (2 * (1 + poisson)));
      if (!((stress - s0) / (strain - e0) > -3 * shear))
        fail(record, line, "the curve softens faster than -3G (G the shear modulus of *ELASTIC)");
    }
    points.emplace_back(stress, strain);
  }
  return curves;
}

}  // namespace

void handle_plastic(const Record& record, DeckState& state) {
  check_params(record, {"HARDENING"});
  const std::string hardening = to_upper(name_value(record, "HARDENING").value_or("ISOTROPIC"));
  model::Material& material = current_material(record, state);
  if (hardening == "ISOTROPIC")
    material.hardening_rule = material::HardeningRule::Isotropic;
  else if (hardening == "KINEMATIC")
    material.hardening_rule = material::HardeningRule::Kinematic;
  else if (hardening == "COMBINED")
    material.hardening_rule = material::HardeningRule::Combined;
  else
    fail(record, "HARDENING=" + hardening +
                     " is not supported (ISOTROPIC, KINEMATIC and COMBINED are)");
  material.plastic = read_hardening_curves(record, material);
}

void handle_cyclic_hardening(const Record& record, DeckState& state) {
  check_params(record, {});
  model::Material& material = current_material(record, state);
  material.cyclic = read_hardening_curves(record, material);
}

void handle_density(const Record& record, DeckState& state) {
  check_params(record, {});
  model::Material& material = current_material(record, state);
  material.density = temperature_table<1>(record, [&](const DataLine& line, const auto& row) {
    if (!(row[0] > 0)) fail(record, line, "density must be positive");
  });
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
  material.expansion = temperature_table<1>(record, [](const DataLine&, const auto&) {});
}

void handle_solid_section(const Record& record, DeckState& state) {
  check_params(record, {"ELSET", "MATERIAL", "OFFSET", "ORIENTATION"});
  // OFFSET= moves plane elements' layer off the z = 0 plane, in thicknesses (ccx).
  Real offset = 0;
  if (const auto* param = find_param(record, "OFFSET")) {
    const std::optional<Real> value = parse_real(param->value);
    if (!value) fail(record, "OFFSET=" + param->value + " is not a number");
    offset = *value;
  }
  // The data line's first field is the thickness of plane stress / strain elements (ccx: a
  // value <= 0 or none means 1) and the cross-sectional area of trusses (kept as given, for
  // truss_builder to check); solids and axisymmetric elements do not use it.
  if (record.lines.size() > 1) fail(record, record.lines[1], "unexpected data line");
  Real thickness = 1;
  std::optional<Real> area;
  if (!record.lines.empty() && !record.lines.front().fields.empty()) {
    area = optional_real_field(record, record.lines.front(), 0);
    if (area && *area > 0) thickness = *area;
  }
  const std::string elset = remove_blanks(to_upper(required_value(record, "ELSET")));
  const std::string material = remove_blanks(to_upper(required_value(record, "MATERIAL")));
  const std::string orientation = name_value(record, "ORIENTATION").value_or("");
  state.sections.push_back(
      RawSection{elset, material, record.where, thickness, offset, orientation, area});
}

void handle_membrane(const Record& record, DeckState& state) {
  // ccx 2.20 does not interpret *MEMBRANE (it skips the card with a warning): a card whose
  // ELSET names no element is skipped here too (c3d6); one that would take elements is
  // refused, as membrane elements are.
  const std::string elset = remove_blanks(to_upper(required_value(record, "ELSET")));
  if (state.element_sets.contains(elset))
    fail(record, "membrane sections are not supported (element set " + elset + ")");
  state.warn(record.where, record.keyword,
             "element set " + elset + " is not defined: the card is ignored (as ccx 2.20 "
             "ignores *MEMBRANE)");
}

void handle_change_solid_section(const Record& record, DeckState& state) {
  check_params(record, {"ELSET", "MATERIAL", "ORIENTATION"});
  if (has_param(record, "ORIENTATION"))
    fail(record, "ORIENTATION= is not supported (the change is between isotropic materials)");
  if (!record.lines.empty())
    fail(record, record.lines.front(), "no data line: ccx does not allow the thickness to change");
  RawSection change;
  change.elset = remove_blanks(to_upper(required_value(record, "ELSET")));
  change.material = remove_blanks(to_upper(required_value(record, "MATERIAL")));
  change.where = record.where;
  state.active.section_changes.push_back(std::move(change));
}

void handle_orientation(const Record& record, DeckState& state) {
  check_params(record, {"NAME", "SYSTEM", "DEFINITION"});
  const std::string name = remove_blanks(to_upper(required_value(record, "NAME")));
  const std::string definition = name_value(record, "DEFINITION").value_or("COORDINATES");
  if (definition != "COORDINATES")
    fail(record, "DEFINITION=" + definition + ": only COORDINATES (two points) is supported");
  const std::string system = name_value(record, "SYSTEM").value_or("RECTANGULAR");
  model::Transform frame;
  if (system == "CYLINDRICAL")
    frame.kind = model::Transform::Kind::Cylindrical;
  else if (system != "RECTANGULAR")
    fail(record, "SYSTEM=" + system + ": expected RECTANGULAR or CYLINDRICAL");
  // ccx allows a second line (an extra rotation about a local axis); not supported here.
  const DataLine& line = read_frame_points(record, frame);
  try {  // a degenerate definition is refused here (x is irrelevant to that)
    (void)model::local_frame(frame, frame.a);
  } catch (const std::invalid_argument& e) {
    fail(record, line, e.what());
  }
  if (!state.orientations.emplace(name, model::Orientation{name, frame}).second)
    fail(record, "orientation " + name + " defined twice");
}

}  // namespace kontakt::inp
