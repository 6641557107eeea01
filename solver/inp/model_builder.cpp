#include "inp/model_builder.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "inp/contact_builder.hpp"
#include "inp/element_names.hpp"
#include "inp/record_access.hpp"
#include "inp/tie_builder.hpp"
#include "material/j2_small_strain.hpp"
#include "model/plane_expansion.hpp"
#include "model/pretension.hpp"

namespace kontakt::inp {

namespace {

/// Members of a raw set as indices via `index` (label -> internal), sorted by label.
std::vector<int> set_members(const RawSet& set, const std::string& name,
                             const DeckState& state, const std::unordered_map<int, int>& index,
                             const char* what, const char* keyword) {
  std::vector<int> members;
  for (const auto& [label, line_id] : set_labels(set, index)) {
    const auto found = index.find(label);
    if (found == index.end()) {
      throw InputError(state.line_locs[static_cast<std::size_t>(line_id)], keyword,
                       std::string(what) + " " + std::to_string(label) + " of set " + name +
                           " is not defined");
    }
    members.push_back(found->second);
  }
  return members;
}

/// Labels of `range` that `index` has, unsorted.
std::vector<int> existing_labels(const model::LabelRange& range,
                                 const std::unordered_map<int, int>& index) {
  std::vector<int> labels;
  if (range.count() <= static_cast<long long>(index.size())) {
    for (long long label = range.first; label <= range.last; label += range.step)
      if (index.contains(static_cast<int>(label))) labels.push_back(static_cast<int>(label));
  } else {
    for (const auto& entry : index)
      if (range.contains(entry.first)) labels.push_back(entry.first);
  }
  return labels;
}

}  // namespace

std::vector<std::pair<int, int>> set_labels(const RawSet& set,
                                            const std::unordered_map<int, int>& index) {
  std::vector<std::pair<int, int>> labelled;  // (label, line id)
  labelled.reserve(set.labels.size());
  for (std::size_t i = 0; i < set.labels.size(); ++i)
    labelled.emplace_back(set.labels[i], set.line_ids[i]);
  for (const model::LabelRange& range : set.ranges)
    for (int label : existing_labels(range, index)) labelled.emplace_back(label, -1);
  std::stable_sort(labelled.begin(), labelled.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  labelled.erase(std::unique(labelled.begin(), labelled.end(),
                             [](const auto& a, const auto& b) { return a.first == b.first; }),
                 labelled.end());
  return labelled;
}

std::vector<int> node_set_members(const DeckState& state, const RawSet& set,
                                  const std::string& name) {
  return set_members(set, name, state, state.model.mesh.node_index, "node", "*NSET");
}

std::vector<int> element_set_members(const DeckState& state, const RawSet& set,
                                     const std::string& name) {
  if (state.connector_index.empty() && state.coupling_elements.empty())
    return set_members(set, name, state, state.model.mesh.element_index, "element", "*ELSET");
  RawSet solids = set;  // without its SPRINGA, GAPUNI and DCOUP3D elements
  std::vector<int> labels, line_ids;
  for (std::size_t i = 0; i < set.labels.size(); ++i)
    if (!state.connector_index.contains(set.labels[i]) &&
        !state.coupling_elements.contains(set.labels[i])) {
      labels.push_back(set.labels[i]);
      line_ids.push_back(set.line_ids[i]);
    }
  solids.labels = std::move(labels);
  solids.line_ids = std::move(line_ids);
  return set_members(solids, name, state, state.model.mesh.element_index, "element", "*ELSET");
}

std::optional<model::Connector::Kind> connector_kind(const DeckState& state, int label) {
  const auto c = state.connector_index.find(label);
  if (c == state.connector_index.end()) return std::nullopt;
  return state.connectors[static_cast<std::size_t>(c->second)].kind;
}

std::vector<int> connector_labels(const DeckState& state, const RawSet& set) {
  std::vector<int> labels;
  for (const auto& [label, line_id] : set_labels(set, state.connector_index))
    if (state.connector_index.contains(label)) labels.push_back(label);
  return labels;
}

int node_index_of(const DeckState& state, const Record& record, const DataLine& line,
                  int label) {
  const auto found = state.model.mesh.node_index.find(label);
  if (found == state.model.mesh.node_index.end()) {
    fail(record, line, "node " + std::to_string(label) + " is not defined");
  }
  return found->second;
}

std::vector<int> resolve_node_field(const DeckState& state, const Record& record,
                                    const DataLine& line, std::size_t field) {
  if (field >= line.fields.size() || line.fields[field].empty()) {
    fail(record, line, "field " + std::to_string(field + 1) + " (node or node set) is missing");
  }
  if (const std::optional<int> label = parse_int(line.fields[field])) {
    return {node_index_of(state, record, line, *label)};
  }
  const std::string name = remove_blanks(to_upper(line.fields[field]));
  const auto set = state.node_sets.find(name);
  if (set == state.node_sets.end()) fail(record, line, "node set " + name + " is not defined");
  return node_set_members(state, set->second, name);
}

std::vector<int> resolve_element_field(const DeckState& state, const Record& record,
                                       const DataLine& line, std::size_t field) {
  if (field >= line.fields.size() || line.fields[field].empty()) {
    fail(record, line, "field " + std::to_string(field + 1) + " (element or set) is missing");
  }
  // Distributed loads (their only users here) would silently pass a truss by.
  const auto refuse_trusses = [&](const std::vector<int>& labels) {
    for (int label : labels)
      if (connector_kind(state, label) == model::Connector::Kind::Truss)
        fail(record, line, "element " + std::to_string(label) +
                               " is a truss (T3D2): distributed loads on trusses are not supported");
  };
  if (const std::optional<int> label = parse_int(line.fields[field])) {
    refuse_trusses({*label});
    const auto found = state.model.mesh.element_index.find(*label);
    if (found == state.model.mesh.element_index.end()) {
      fail(record, line, "element " + std::to_string(*label) + " is not defined");
    }
    return {found->second};
  }
  const std::string name = remove_blanks(to_upper(line.fields[field]));
  const auto set = state.element_sets.find(name);
  if (set == state.element_sets.end()) {
    fail(record, line, "element set " + name + " is not defined");
  }
  refuse_trusses(connector_labels(state, set->second));
  return element_set_members(state, set->second, name);
}

int amplitude_param(DeckState& state, const Record& record) {
  const std::optional<std::string> name = name_value(record, "AMPLITUDE");
  const std::optional<std::string> delay_text = name_value(record, "TIMEDELAY");
  if (!name) {
    if (delay_text) fail(record, "TIME DELAY shifts an amplitude: AMPLITUDE= is missing");
    return -1;
  }
  const auto found = state.amplitude_index.find(*name);
  if (found == state.amplitude_index.end()) fail(record, "amplitude " + *name + " is not defined");
  if (!delay_text) return found->second;
  const std::optional<Real> delay = parse_real(*delay_text);
  if (!delay) fail(record, "TIME DELAY=" + *delay_text + " is not a number");
  // As ccx: the card gets its own copy of the amplitude, moved later in time by the delay.
  model::Amplitude shifted = state.model.amplitudes[static_cast<std::size_t>(found->second)];
  shifted.name += " (TIME DELAY=" + *delay_text + ")";
  for (auto& point : shifted.points) point.first += *delay;
  state.model.amplitudes.push_back(std::move(shifted));
  return static_cast<int>(state.model.amplitudes.size()) - 1;
}

namespace {

void resolve_connectivity(DeckState& state) {
  model::Mesh& mesh = state.model.mesh;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    model::Element& element = mesh.elements[e];
    element.nodes.reserve(state.element_node_labels[e].size());
    for (int label : state.element_node_labels[e]) {
      const auto found = mesh.node_index.find(label);
      if (found == mesh.node_index.end()) {
        throw InputError(state.line_locs[static_cast<std::size_t>(state.element_line_ids[e])],
                         "*ELEMENT", "node " + std::to_string(label) + " of element " +
                                         std::to_string(element.id) + " is not defined");
      }
      element.nodes.push_back(found->second);
    }
  }
}

/// ccx 2.20 drops the labels of a node set beyond the deck's largest node label, with a
/// warning (scheibe names node 29, a node of its 2D element's expansion): so does Kontakt. A
/// missing label below the largest stays an error (ccx would print it as a node at rest).
void drop_nodes_beyond_the_mesh(DeckState& state) {
  int largest = 0;
  for (const auto& entry : state.model.mesh.node_index) largest = std::max(largest, entry.first);
  for (auto& [name, set] : state.node_sets) {
    std::vector<int> labels, line_ids;
    for (std::size_t i = 0; i < set.labels.size(); ++i) {
      if (set.labels[i] <= largest) {
        labels.push_back(set.labels[i]);
        line_ids.push_back(set.line_ids[i]);
        continue;
      }
      state.warn(state.line_locs[static_cast<std::size_t>(set.line_ids[i])], "*NSET",
                 "node " + std::to_string(set.labels[i]) + " of set " + name +
                     " is beyond the largest node label " + std::to_string(largest) +
                     ": left out of the set (as ccx does)");
    }
    set.labels = std::move(labels);
    set.line_ids = std::move(line_ids);
    std::erase_if(set.sequence, [&](const model::LabelRange& r) { return r.first > largest; });
  }
}

void build_sets(DeckState& state) {
  for (const auto& [name, set] : state.node_sets) {
    state.model.node_sets[name] =
        model::NodeSet{name, node_set_members(state, set, name), set.sequence};
  }
  for (const auto& [name, set] : state.element_sets) {
    state.model.element_sets[name] =
        model::ElementSet{name, element_set_members(state, set, name), set.sequence};
  }
}

model::Surface build_surface(const DeckState& state, const std::string& name,
                             const RawSurface& raw) {
  const model::Mesh& mesh = state.model.mesh;
  model::Surface surface{name, raw.kind, {}, {}, raw.where};
  std::set<std::pair<int, int>> seen_faces;
  for (const RawFace& face : raw.faces) {
    const SourceLoc& where = state.line_locs[static_cast<std::size_t>(face.line_id)];
    const auto found = mesh.element_index.find(face.element_label);
    if (const auto kind = connector_kind(state, face.element_label))
      throw InputError(where, "*SURFACE",
                       "element " + std::to_string(face.element_label) + " is a " +
                           std::string(model::connector_type_name(*kind)) +
                           " element: it has no faces for a surface (contact on trusses, springs "
                           "and gaps is not supported)");
    if (found == mesh.element_index.end()) {
      throw InputError(where, "*SURFACE",
                       "element " + std::to_string(face.element_label) + " is not defined");
    }
    const model::Element& element = mesh.elements[found->second];
    const ElementName& type = element_name_of(element.type, element.planar);
    if (face.face > type.n_faces) {
      throw InputError(where, "*SURFACE", "element " + std::to_string(face.element_label) +
                                              " (" + std::string(type.name) + ") has no face S" +
                                              std::to_string(face.face));
    }
    // A face named twice (overlapping sets, a repeated *SURFACE) is one face, as in ccx.
    if (seen_faces.insert({found->second, face.face}).second)
      surface.faces.push_back(model::ElementFace{found->second, face.face});
  }
  for (std::size_t i = 0; i < raw.node_labels.size(); ++i) {
    const auto found = mesh.node_index.find(raw.node_labels[i]);
    if (found == mesh.node_index.end()) {
      throw InputError(state.line_locs[static_cast<std::size_t>(raw.line_ids[i])], "*SURFACE",
                       "node " + std::to_string(raw.node_labels[i]) + " is not defined");
    }
    surface.nodes.push_back(found->second);
  }
  std::sort(surface.nodes.begin(), surface.nodes.end());
  surface.nodes.erase(std::unique(surface.nodes.begin(), surface.nodes.end()), surface.nodes.end());
  return surface;
}

/// *DEFORMATION PLASTICITY stands alone, in NLGEOM steps (the total Lagrangian kernels carry
/// it), and has no energy to print (ccx's ENER of it is not known here).
void require_deformation_plasticity_support(const model::Model& model, const model::Material& mat) {
  if (mat.hyperelastic || !mat.plastic.empty() || !mat.elastic.empty() || !mat.anisotropic.empty())
    throw InputError(mat.where, "*MATERIAL",
                     "material " + mat.name + ": *DEFORMATION PLASTICITY stands alone (no *ELASTIC, "
                                              "*PLASTIC, *HYPERELASTIC or *HYPERFOAM)");
  for (const model::Step& step : model.steps) {
    if (!step.nlgeom)
      throw InputError(step.where, "*STEP",
                       "material " + mat.name + " has *DEFORMATION PLASTICITY: every step needs "
                                                "NLGEOM");
    for (const model::PrintRequest& print : step.prints)
      for (const std::string& variable : print.variables)
        if (variable == "ENER" || variable == "ELSE")
          throw InputError(print.where, "*EL PRINT",
                           variable + " of material " + mat.name +
                               " (*DEFORMATION PLASTICITY) is not available");
  }
}

/// *MODEL CHANGE, TYPE=ELEMENT in models whose elements carry nothing but their displacements:
/// no contact, ties, plastic points or C3D8I modes (their states at removal are not defined
/// here), no plane elements or pre-tension cuts (which renumber or copy nodes).
void require_element_change_support(const DeckState& state) {
  if (!state.element_change_where) return;
  const model::Model& model = state.model;
  const auto refuse = [&](const std::string& why) {
    throw InputError(*state.element_change_where, "*MODEL CHANGE",
                     "TYPE=ELEMENT is not supported " + why);
  };
  if (!model.contact_pairs.empty() || !model.ties.empty()) refuse("with contact or *TIE");
  if (!model.pretension_sections.empty()) refuse("with *PRE-TENSION SECTION");
  for (const model::Element& el : model.mesh.elements) {
    if (el.planar != model::Planar::None) refuse("with plane or axisymmetric elements");
    if (el.type == element::ElementType::C3D8I) refuse("with C3D8I elements");
    const model::SolidSection& section = model.sections[static_cast<std::size_t>(el.section)];
    if (!model.materials[static_cast<std::size_t>(section.material)].plastic.empty())
      refuse("with *PLASTIC materials");
  }
}

/// KINEMATIC and COMBINED hardening run in the finite-strain kernels (NLGEOM steps; ccx switches
/// NLGEOM on for *PLASTIC anyway); COMBINED needs its *CYCLIC HARDENING curve, which nothing
/// else reads.
void require_hardening_support(const model::Model& model, const model::Material& mat) {
  using material::HardeningRule;
  const std::string rule = mat.hardening_rule == HardeningRule::Kinematic ? "KINEMATIC" : "COMBINED";
  if (!mat.cyclic.empty() && mat.hardening_rule != HardeningRule::Combined)
    throw InputError(mat.where, "*CYCLIC HARDENING",
                     "material " + mat.name + ": *CYCLIC HARDENING needs *PLASTIC, "
                                              "HARDENING=COMBINED");
  if (mat.hardening_rule == HardeningRule::Isotropic) return;
  if (mat.hardening_rule == HardeningRule::Combined && mat.cyclic.empty())
    throw InputError(mat.where, "*PLASTIC",
                     "material " + mat.name + ": HARDENING=COMBINED needs a *CYCLIC HARDENING "
                                              "curve (the yield surface's size)");
  if (mat.plastic.curves.size() > 1 || mat.cyclic.curves.size() > 1)
    throw InputError(mat.where, "*PLASTIC",
                     "material " + mat.name + ": HARDENING=" + rule +
                         " with curves by temperature is not supported (one curve)");
  for (const model::Step& step : model.steps)
    if (!step.nlgeom)
      throw InputError(step.where, "*STEP",
                       "material " + mat.name + " hardens " + rule +
                           " (*PLASTIC): every step needs NLGEOM");
}

void assign_sections(DeckState& state) {
  model::Model& model = state.model;
  for (const RawSection& raw : state.sections) {
    const auto material = state.material_index.find(raw.material);
    if (material == state.material_index.end()) {
      throw InputError(raw.where, "*SOLID SECTION", "material " + raw.material +
                                                        " is not defined");
    }
    const model::Material& mat = model.materials[static_cast<std::size_t>(material->second)];
    if (!mat.has_elastic()) {
      throw InputError(raw.where, "*SOLID SECTION",
                       "material " + raw.material + " has no *ELASTIC constants");
    }
    if (mat.hyperelastic && (!mat.plastic.empty() || !mat.elastic.empty() ||
                             !mat.anisotropic.empty()))
      throw InputError(mat.where, "*MATERIAL",
                       "material " + mat.name + ": *HYPERELASTIC / *HYPERFOAM stands alone here "
                                                "(no *ELASTIC, no *PLASTIC)");
    if (mat.hyperelastic) {  // the linear kernels have no hyperelastic law
      for (const model::Step& step : model.steps)
        if (!step.nlgeom)
          throw InputError(step.where, "*STEP",
                           "material " + mat.name + " is hyperelastic: every step needs NLGEOM");
    }
    if (mat.deformation_plasticity) require_deformation_plasticity_support(model, mat);
    require_hardening_support(model, mat);
    if (!mat.anisotropic.empty() && !mat.plastic.empty())
      throw InputError(mat.where, "*MATERIAL",
                       "material " + mat.name + ": *PLASTIC needs an isotropic *ELASTIC "
                                                "(TYPE=ISO); orthotropic or anisotropic "
                                                "plasticity is not supported");
    const auto elset = model.element_sets.find(raw.elset);
    if (elset == model.element_sets.end()) {
      throw InputError(raw.where, "*SOLID SECTION", "element set " + raw.elset +
                                                        " is not defined");
    }
    std::optional<model::Orientation> orientation;
    if (!raw.orientation.empty()) {
      const auto found = state.orientations.find(raw.orientation);
      if (found == state.orientations.end())
        throw InputError(raw.where, "*SOLID SECTION",
                         "orientation " + raw.orientation + " is not defined");
      orientation = found->second;
    }
    const int section = static_cast<int>(model.sections.size());
    model.sections.push_back(model::SolidSection{raw.elset, material->second, raw.where,
                                                 raw.thickness, raw.offset, orientation});
    for (int e : elset->second.elements) {
      model::Element& element = model.mesh.elements[static_cast<std::size_t>(e)];
      if (element.section >= 0) {
        state.warn(raw.where, "*SOLID SECTION",
                   "element " + std::to_string(element.id) + " already had a section; replaced");
      }
      // C3D8R's hourglass stiffness is scaled by Young's modulus, which an anisotropic
      // material does not have (ccx's choice for it is not known here).
      if (element.type == element::ElementType::C3D8R &&
          (!mat.anisotropic.empty() || mat.hyperelastic || mat.deformation_plasticity))
        throw InputError(raw.where, "*SOLID SECTION",
                         "element " + std::to_string(element.id) +
                             " is a C3D8R: its hourglass control needs an isotropic *ELASTIC, "
                             "and " + mat.name + " is orthotropic, anisotropic, hyperelastic or "
                             "deformation plastic");
      element.section = section;
    }
  }
}

void require_sections(const DeckState& state) {
  const auto& elements = state.model.mesh.elements;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (elements[e].section >= 0) continue;
    throw InputError(state.line_locs[static_cast<std::size_t>(state.element_line_ids[e])],
                     "*ELEMENT", "element " + std::to_string(elements[e].id) +
                                     " has no *SOLID SECTION");
  }
}

/// GRAV and CENTRIF act on the mass: every loaded element's material needs a *DENSITY (one
/// value: the body forces do not evaluate it at the points' temperatures).
void require_densities(const DeckState& state) {
  const model::Model& model = state.model;
  for (const model::Step& step : model.steps) {
    for (const model::BodyLoad& load : step.body_loads) {
      for (int e : load.elements) {
        const model::Element& element = model.mesh.elements[static_cast<std::size_t>(e)];
        const model::Material& material =
            model.materials[static_cast<std::size_t>(model.sections[element.section].material)];
        if (material.density.empty()) {
          throw InputError(load.where, "*DLOAD",
                           "element " + std::to_string(element.id) + " has material " +
                               material.name + " without *DENSITY; GRAV and CENTRIF need it");
        }
        if (material.density.rows.size() > 1) {
          throw InputError(load.where, "*DLOAD",
                           "material " + material.name + " of element " +
                               std::to_string(element.id) +
                               " has a temperature-dependent *DENSITY: GRAV and CENTRIF take a "
                               "constant density only");
        }
      }
    }
  }
}

/// An initial inelastic strain of an elastic material is the initial stress -C eps_p (ccx's
/// TYPE=PLASTIC STRAIN, tensor shear components): the stress is then C (eps - eps_p) from the
/// first increment on. A *PLASTIC material would need the strain in its plastic state, and a
/// temperature-dependent or anisotropic one the stiffness at each point: both are refused.
void add_initial_inelastic_strains(DeckState& state) {
  model::Model& model = state.model;
  if (!state.initial_inelastic_strain_where) return;
  const auto refuse = [&](const std::string& why) {
    throw InputError(*state.initial_inelastic_strain_where, "*INITIAL CONDITIONS",
                     "TYPE=PLASTIC STRAIN is supported for isotropic elastic materials with "
                     "constant constants only: " + why);
  };
  model.initial_stresses.resize(model.mesh.elements.size());
  state.initial_inelastic_strains.resize(model.mesh.elements.size());
  for (std::size_t e = 0; e < model.mesh.elements.size(); ++e) {
    const MatX& strain = state.initial_inelastic_strains[e];
    if (strain.size() == 0) continue;
    const model::Element& element = model.mesh.elements[e];
    const model::Material& material =
        model.materials[static_cast<std::size_t>(model.sections[element.section].material)];
    const std::string name = "element " + std::to_string(element.id) + " (material " +
                             material.name + ")";
    if (!material.plastic.empty()) refuse(name + " has *PLASTIC");
    if (material.elastic.rows.size() != 1) refuse(name + " is not isotropic with one *ELASTIC row");
    const auto [young, poisson] = material.elastic.rows.front();
    const Mat6 stiffness = material::isotropic_elastic_stiffness(young, poisson);
    const Vec6 engineering_shear = (Vec6() << 1, 1, 1, 2, 2, 2).finished();
    MatX& sigma0 = model.initial_stresses[e];
    if (sigma0.size() == 0) sigma0 = MatX::Zero(strain.rows(), 6);
    for (Eigen::Index ip = 0; ip < strain.rows(); ++ip)
      sigma0.row(ip) -= (stiffness * strain.row(ip).transpose().cwiseProduct(engineering_shear))
                            .transpose();
  }
  if (!state.initial_stress_where) state.initial_stress_where = state.initial_inelastic_strain_where;
}

/// Initial stresses enter the small-strain elastic kernels only: refuse where another kernel
/// (finite strain, plasticity, incompatible modes, 2D expansion) would have to carry them.
void require_initial_stress_support(DeckState& state) {
  model::Model& model = state.model;
  if (!state.initial_stress_where) return;
  model.initial_stresses.resize(model.mesh.elements.size());
  const auto refuse = [&](const std::string& why) {
    throw InputError(*state.initial_stress_where, "*INITIAL CONDITIONS",
                     "TYPE=STRESS is supported for small-strain elastic solid elements only: " + why);
  };
  for (const model::Step& step : model.steps)
    if (step.nlgeom) refuse("a step has NLGEOM");
  for (std::size_t e = 0; e < model.initial_stresses.size(); ++e) {
    if (model.initial_stresses[e].size() == 0) continue;
    const model::Element& element = model.mesh.elements[e];
    const std::string name = "element " + std::to_string(element.id);
    if (element.planar != model::Planar::None) refuse(name + " is a 2D element");
    if (element.type == element::ElementType::C3D8I) refuse(name + " is a C3D8I");
    const model::Material& material =
        model.materials[static_cast<std::size_t>(model.sections[element.section].material)];
    if (!material.plastic.empty()) refuse(name + " has a *PLASTIC material");
  }
}

/// Step::element_sections from the *CHANGE SOLID SECTION cards in force in each step. Linear
/// analyses of isotropic elastic materials only: the nonlinear drivers read the elements' own
/// sections, and a plastic or hyperelastic state has no meaning under another law.
void resolve_section_changes(DeckState& state) {
  model::Model& model = state.model;
  std::map<std::pair<int, int>, int> changed_section;  // (section, material) -> section
  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const std::vector<RawSection>& changes = state.step_section_changes[s];
    if (changes.empty()) continue;
    const auto refuse = [&](const RawSection& change, const std::string& why) {
      throw InputError(change.where, "*CHANGE SOLID SECTION", why);
    };
    const RawSection& first = changes.front();
    for (const model::Step& step : model.steps)
      if (step.nlgeom) refuse(first, "not supported with NLGEOM steps (linear analyses only)");
    if (!model.contact_pairs.empty() || !model.ties.empty())
      refuse(first, "not supported with contact or ties (linear analyses only)");
    for (const model::Material& mat : model.materials)
      if (!mat.plastic.empty())
        refuse(first, "not supported in a deck with *PLASTIC (linear analyses only)");
    std::vector<int>& sections = model.steps[s].element_sections;
    for (const model::Element& el : model.mesh.elements) sections.push_back(el.section);
    for (const RawSection& change : changes) {
      const auto material = state.material_index.find(change.material);
      if (material == state.material_index.end())
        refuse(change, "material " + change.material + " is not defined");
      const model::Material& mat = model.materials[static_cast<std::size_t>(material->second)];
      if (mat.elastic.empty())
        refuse(change, "material " + change.material + " needs an isotropic *ELASTIC");
      const auto elset = model.element_sets.find(change.elset);
      if (elset == model.element_sets.end())
        refuse(change, "element set " + change.elset + " is not defined");
      for (int label : connector_labels(state, state.element_sets.at(change.elset)))
        if (connector_kind(state, label) == model::Connector::Kind::Truss)
          refuse(change, "element " + std::to_string(label) +
                             " is a truss (T3D2): its section cannot change (solids only)");
      for (int e : elset->second.elements) {
        int& section = sections[static_cast<std::size_t>(e)];
        if (section < 0) continue;  // no section before: the deck's own check reports it
        const model::SolidSection old = model.sections[static_cast<std::size_t>(section)];
        if (old.orientation || model.materials[static_cast<std::size_t>(old.material)].elastic.empty())
          refuse(change, "element " + std::to_string(model.mesh.elements[static_cast<std::size_t>(e)].id) +
                             " is not of an isotropic *ELASTIC material without orientation");
        const auto key = std::make_pair(section, material->second);
        auto [it, fresh] = changed_section.try_emplace(key, static_cast<int>(model.sections.size()));
        if (fresh)
          model.sections.push_back(model::SolidSection{change.elset, material->second, change.where,
                                                       old.thickness, old.offset, std::nullopt});
        section = it->second;
      }
    }
  }
}

}  // namespace

model::Model finish_model(DeckState& state) {
  if (state.open_step) {
    throw InputError(state.open_step->step.where, "*STEP", "missing *END STEP at end of deck");
  }
  model::Model& model = state.model;
  model.mesh.coords.resize(static_cast<Eigen::Index>(state.coords.size()), 3);
  for (std::size_t i = 0; i < state.coords.size(); ++i) {
    model.mesh.coords.row(static_cast<Eigen::Index>(i)) = state.coords[i].transpose();
  }
  resolve_connectivity(state);
  drop_nodes_beyond_the_mesh(state);
  build_sets(state);
  for (const auto& [name, raw] : state.surfaces) {
    model.surfaces[name] = build_surface(state, name, raw);
  }
  assign_sections(state);
  require_sections(state);
  require_densities(state);
  add_initial_inelastic_strains(state);
  require_initial_stress_support(state);
  resolve_contact(state);
  resolve_ties(state);
  resolve_rigid_bodies(state);
  resolve_connectors(state);
  assign_truss_sections(state);
  resolve_couplings(state);
  resolve_section_changes(state);
  require_element_change_support(state);
  if (!state.initial_temperatures.empty()) {
    model.initial_temperatures = VecX::Zero(model.n_nodes());
    for (const auto& [node, value] : state.initial_temperatures) {
      model.initial_temperatures[node] = value;
    }
  }
  std::vector<SourceLoc> element_where;
  element_where.reserve(state.element_line_ids.size());
  for (int id : state.element_line_ids)
    element_where.push_back(state.line_locs[static_cast<std::size_t>(id)]);
  model::expand_planar_elements(model, element_where);
  model::split_pretension_sections(model);
  return std::move(model);
}

}  // namespace kontakt::inp
