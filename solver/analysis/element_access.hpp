// Gathering one element's data from the model, shared by the analysis drivers.
#pragma once

#include <string>

#include "element/initial_stress.hpp"
#include "element/solid_linear.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

inline MatX3 element_coords(const model::Model& model, const model::Element& el) {
  MatX3 X(el.nodes.size(), 3);
  for (std::size_t a = 0; a < el.nodes.size(); ++a) X.row(a) = model.mesh.coords.row(el.nodes[a]);
  return X;
}

/// The element's section: in `step` when given (*CHANGE SOLID SECTION), else its own. `el`
/// must be an element of model.mesh.elements.
inline const model::SolidSection& element_section(const model::Model& model,
                                                  const model::Element& el,
                                                  const model::Step* step = nullptr) {
  const auto e = static_cast<std::size_t>(&el - model.mesh.elements.data());
  const int section = step && !step->element_sections.empty() ? step->element_sections[e]
                                                              : el.section;
  return model.sections[static_cast<std::size_t>(section)];
}

inline const model::Material& element_material_def(const model::Model& model,
                                                   const model::Element& el,
                                                   const model::Step* step = nullptr) {
  return model.materials[element_section(model, el, step).material];
}

/// Whether some material's elastic constants follow the temperature (a stiffness then changes
/// with the temperature field and cannot be reused across temperatures).
inline bool any_temperature_dependent_stiffness(const model::Model& model) {
  for (const auto& m : model.materials)
    if (m.elastic.rows.size() > 1 || m.anisotropic.rows.size() > 1) return true;
  return false;
}

/// Nodal values of one element gathered from a per-node vector.
inline VecX element_values(const model::Element& el, const VecX& nodal) {
  VecX v(el.nodes.size());
  for (std::size_t a = 0; a < el.nodes.size(); ++a) v[a] = nodal[el.nodes[a]];
  return v;
}

/// The element's elastic material with its nodes' initial temperatures, which the
/// temperature-dependent constants and thermal strain are evaluated from.
inline element::ThermoElastic element_material(const model::Model& model,
                                               const model::Element& el,
                                               const model::Step* step = nullptr) {
  const auto& mat = element_material_def(model, el, step);
  element::ThermoElastic m;
  m.elastic = mat.elastic;
  m.anisotropic = mat.anisotropic;
  m.hyperelastic = mat.hyperelastic;
  m.deformation_plasticity = mat.deformation_plasticity;
  const auto& orientation = element_section(model, el, step).orientation;
  if (orientation && !mat.anisotropic.empty()) {  // an isotropic material has no frame
    m.frame = [t = orientation->frame](const Vec3& x) { return model::local_frame(t, x); };
    m.coords = element_coords(model, el);
  }
  m.expansion = mat.expansion;
  m.expansion_zero = mat.expansion_zero;
  if (model.initial_temperatures.size()) {
    m.initial_temperature = element_values(el, model.initial_temperatures);
  }
  return m;
}

/// An element's initial stress (*INITIAL CONDITIONS, TYPE=STRESS; n_ip x 6), null when it has
/// none. `el` must be an element of model.mesh.elements (its index there selects the stress).
inline const MatX* element_initial_stress(const model::Model& model, const model::Element& el) {
  const auto e = static_cast<std::size_t>(&el - model.mesh.elements.data());
  if (e >= model.initial_stresses.size() || model.initial_stresses[e].size() == 0) return nullptr;
  return &model.initial_stresses[e];
}

/// Adds an element's initial stress, if any, to its point stresses (n_ip x 6) and internal
/// force (3n) from the small-strain elastic kernel.
inline void add_initial_stress(const model::Model& model, const model::Element& el,
                               const MatX3& X, MatX6& stress, VecX& internal_force) {
  const MatX* sigma0 = element_initial_stress(model, el);
  if (!sigma0) return;
  VecX f0;
  element::initial_stress_force(el.type, X, *sigma0, f0);
  stress += *sigma0;
  internal_force += f0;
}

/// Displacements of one element's nodes (n x 3) from the full dof vector.
inline MatX3 element_displacements(const model::Element& el, const VecX& u) {
  MatX3 ue(el.nodes.size(), 3);
  for (std::size_t a = 0; a < el.nodes.size(); ++a) ue.row(a) = u.segment<3>(3 * el.nodes[a]);
  return ue;
}

/// Runs an element kernel; a failure inside it (e.g. an inverted element) names the element.
template <class Fn>
void naming_element(const model::Element& el, Fn&& fn) {
  try {
    fn();
  } catch (const SolverError& e) {
    throw SolverError("element " + std::to_string(el.id) + " (" +
                      std::string(element::traits(el.type).name) + "): " + e.what());
  }
}

}  // namespace kontakt::analysis
