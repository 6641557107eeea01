#include "model/pretension.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "element/element_type.hpp"

namespace kontakt::model {

namespace {

constexpr const char* kKeyword = "*PRE-TENSION SECTION";

std::string label(const Model& model, int node) {
  return std::to_string(model.mesh.node_ids[static_cast<std::size_t>(node)]);
}

const Surface& section_surface(const Model& model, const PretensionSection& section) {
  const auto found = model.surfaces.find(section.surface);
  if (found == model.surfaces.end())
    throw InputError(section.where, kKeyword, "surface " + section.surface + " is not defined");
  const Surface& surface = found->second;
  if (surface.kind != Surface::Kind::ElementFaces)
    throw InputError(section.where, kKeyword,
                     "surface " + section.surface +
                         " is a node surface: a pre-tension section is made of element faces");
  if (surface.faces.empty())
    throw InputError(section.where, kKeyword, "surface " + section.surface + " is empty");
  return surface;
}

/// The section's nodes in order of first appearance (ccx numbers the copies so).
std::vector<int> section_nodes(const Model& model, const Surface& surface) {
  std::vector<int> nodes;
  std::set<int> seen;
  for (const ElementFace& face : surface.faces) {
    const Element& element = model.mesh.elements[static_cast<std::size_t>(face.element)];
    for (int local : element::face_nodes(element.type, face.face))
      if (seen.insert(element.nodes[static_cast<std::size_t>(local)]).second)
        nodes.push_back(element.nodes[static_cast<std::size_t>(local)]);
  }
  return nodes;
}

VecX extended(const VecX& values, const std::vector<int>& source_of_new_node) {
  if (values.size() == 0) return values;
  VecX out(values.size() + static_cast<Index>(source_of_new_node.size()));
  out.head(values.size()) = values;
  for (std::size_t k = 0; k < source_of_new_node.size(); ++k)
    out[values.size() + static_cast<Index>(k)] = values[source_of_new_node[k]];
  return out;
}

}  // namespace

void split_pretension_sections(Model& model) {
  if (model.pretension_sections.empty()) return;
  Mesh& mesh = model.mesh;
  int next_label = 1;
  for (int id : mesh.node_ids) next_label = std::max(next_label, id + 1);
  std::vector<char> in_element(static_cast<std::size_t>(model.n_nodes()), 0);
  for (const Element& element : mesh.elements)
    for (int n : element.nodes) in_element[static_cast<std::size_t>(n)] = 1;

  // Every section's nodes from the uncut mesh first: a node in two sections is refused, not
  // cut twice.
  std::vector<std::vector<int>> nodes_of_section;
  std::map<int, const PretensionSection*> section_of_node;
  for (const PretensionSection& section : model.pretension_sections) {
    if (in_element[static_cast<std::size_t>(section.node)])
      throw InputError(section.where, kKeyword,
                       "reference node " + label(model, section.node) +
                           " belongs to an element; it must be a node of its own");
    nodes_of_section.push_back(section_nodes(model, section_surface(model, section)));
    for (int node : nodes_of_section.back()) {
      const auto [other, fresh] = section_of_node.emplace(node, &section);
      if (!fresh)
        throw InputError(section.where, kKeyword,
                         "node " + label(model, node) + " is also in the pre-tension section at " +
                             other->second->where.file + ":" +
                             std::to_string(other->second->where.line));
    }
  }

  std::vector<int> source_of_new_node;
  for (std::size_t s = 0; s < model.pretension_sections.size(); ++s) {
    const PretensionSection& section = model.pretension_sections[s];
    std::map<int, int> copy_of;
    for (int node : nodes_of_section[s]) {
      const int copy = model.n_nodes();
      mesh.node_ids.push_back(next_label);
      mesh.node_index.emplace(next_label, copy);
      ++next_label;
      mesh.coords.conservativeResize(copy + 1, 3);
      mesh.coords.row(copy) = mesh.coords.row(node);
      source_of_new_node.push_back(node);
      copy_of[node] = copy;
      for (int k = 0; k < 3; ++k) {
        std::vector<EquationTerm> terms{{copy, k, 1.0}, {node, k, -1.0}};
        if (section.normal[k] != 0) terms.push_back({section.node, 0, -section.normal[k]});
        model.equations.push_back(Equation{std::move(terms), section.where, kKeyword});
      }
    }
    for (const ElementFace& face : model.surfaces.at(section.surface).faces)
      for (int& n : mesh.elements[static_cast<std::size_t>(face.element)].nodes)
        if (const auto found = copy_of.find(n); found != copy_of.end()) n = found->second;
  }
  model.initial_temperatures = extended(model.initial_temperatures, source_of_new_node);
  for (Step& step : model.steps) step.temperatures = extended(step.temperatures, source_of_new_node);
}

}  // namespace kontakt::model
