// Hand-built small models for assembly tests: no deck reader involved.
#pragma once

#include "model/model.hpp"

namespace kontakt::fixtures {

/// A row of `n_elements` 8-node bricks along x (unit cubes), node labels 1.., element labels 1...
inline model::Model brick_row(int n_elements) {
  model::Model m;
  const int n_nodes = 4 * (n_elements + 1);
  m.mesh.coords.resize(n_nodes, 3);
  for (int i = 0; i <= n_elements; ++i)
    for (int k = 0; k < 4; ++k) {
      const int node = 4 * i + k;
      m.mesh.coords.row(node) << i, (k == 1 || k == 2) ? 1 : 0, k >= 2 ? 1 : 0;
      m.mesh.node_ids.push_back(node + 1);
      m.mesh.node_index[node + 1] = node;
    }
  for (int i = 0; i < n_elements; ++i) {
    model::Element el;
    el.id = i + 1;
    el.type = element::ElementType::C3D8;
    const int a = 4 * i, b = 4 * (i + 1);
    el.nodes = {a, b, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2};
    m.mesh.element_index[el.id] = i;
    m.mesh.elements.push_back(el);
  }
  return m;
}

}  // namespace kontakt::fixtures
