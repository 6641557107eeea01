// T3D2 trusses take their material and cross-sectional area from *SOLID SECTION (ccx manual:
// *SOLID SECTION, T3D2). Only what the axial bar of analysis/truss models is accepted.
#include <string>

#include "inp/model_builder.hpp"

namespace kontakt::inp {

namespace {

/// Why `mat` cannot make a truss here, or empty when it can.
std::string truss_material_refusal(const model::Material& mat, bool has_temperatures) {
  if (!mat.plastic.empty()) return "*PLASTIC";
  if (mat.hyperelastic) return "*HYPERELASTIC";
  if (mat.deformation_plasticity) return "*DEFORMATION PLASTICITY";
  if (!mat.anisotropic.empty()) return "an orthotropic or anisotropic *ELASTIC";
  if (mat.elastic.rows.size() > 1) return "a temperature-dependent *ELASTIC";
  // No thermal strain in the bar: with temperatures its expansion would be dropped.
  if (!mat.expansion.empty() && has_temperatures) return "*EXPANSION with temperatures";
  return "";
}

}  // namespace

void assign_truss_sections(DeckState& state) {
  model::Model& model = state.model;
  std::vector<const RawSection*> section_of(model.connectors.size(), nullptr);
  for (const RawSection& raw : state.sections) {  // the last card naming a truss wins
    const auto set = state.element_sets.find(raw.elset);
    if (set == state.element_sets.end()) continue;  // assign_sections has reported it
    for (int label : connector_labels(state, set->second))
      section_of[static_cast<std::size_t>(state.connector_index.at(label))] = &raw;
  }
  bool has_temperatures = !state.initial_temperatures.empty();
  for (const model::Step& step : model.steps) has_temperatures |= step.temperatures.size() > 0;

  for (std::size_t k = 0; k < model.connectors.size(); ++k) {
    model::Connector& c = model.connectors[k];
    if (c.kind != model::Connector::Kind::Truss) continue;
    const std::string name = "truss element " + std::to_string(c.id);
    if (!section_of[k])
      throw InputError(c.where, "*ELEMENT",
                       name + " has no *SOLID SECTION (its material and cross-sectional area)");
    const RawSection& section = *section_of[k];
    const auto refuse = [&](const std::string& why) {
      throw InputError(section.where, "*SOLID SECTION", name + ": " + why);
    };
    if (!section.area)
      refuse("the data line must give the cross-sectional area");
    if (!(*section.area > 0))
      refuse("the cross-sectional area must be positive, got " + std::to_string(*section.area));
    if (!section.orientation.empty())
      refuse("ORIENTATION= is not supported for trusses (their material is isotropic)");
    const model::Material& mat =
        model.materials[static_cast<std::size_t>(state.material_index.at(section.material))];
    if (const std::string why = truss_material_refusal(mat, has_temperatures); !why.empty())
      refuse("material " + mat.name + " has " + why +
             ": trusses take an isotropic *ELASTIC with one row of constants");
    if (mat.elastic.empty()) refuse("material " + mat.name + " has no isotropic *ELASTIC");
    c.area = *section.area;
    c.young = mat.elastic.rows.front()[0];
    c.poisson = mat.elastic.rows.front()[1];
  }
}

}  // namespace kontakt::inp
