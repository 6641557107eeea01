// Small hand-built models for the output tests.
#pragma once

#include <utility>
#include <vector>

#include "model/model.hpp"

namespace kontakt::output::test {

inline void add_node(model::Model& m, int label, double x, double y, double z) {
  const int i = m.n_nodes();
  m.mesh.node_ids.push_back(label);
  m.mesh.coords.conservativeResize(i + 1, 3);
  m.mesh.coords.row(i) << x, y, z;
  m.mesh.node_index[label] = i;
}

inline void add_element(model::Model& m, int label, element::ElementType t,
                        std::vector<int> nodes) {
  const int i = m.n_elements();
  model::Element e;
  e.id = label;
  e.type = t;
  e.nodes = std::move(nodes);
  m.mesh.elements.push_back(e);
  m.mesh.element_index[label] = i;
}

/// Two C3D4 tetrahedra, node labels 10..50, element labels 7 and 8; sets NALL, FIX, EALL.
inline model::Model two_tets() {
  model::Model m;
  add_node(m, 10, 0, 0, 0);
  add_node(m, 20, 1, 0, 0);
  add_node(m, 30, 0, 1, 0);
  add_node(m, 40, 0, 0, 1);
  add_node(m, 50, 1, 1, 1);
  add_element(m, 7, element::ElementType::C3D4, {0, 1, 2, 3});
  add_element(m, 8, element::ElementType::C3D4, {1, 4, 2, 3});
  m.node_sets["NALL"] = {"NALL", {0, 1, 2, 3, 4}};
  m.node_sets["FIX"] = {"FIX", {0, 1}};
  m.element_sets["EALL"] = {"EALL", {0, 1}};
  m.element_sets["E2"] = {"E2", {1}};
  m.steps.resize(1);
  return m;
}

}  // namespace kontakt::output::test
