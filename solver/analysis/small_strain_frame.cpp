#include "analysis/small_strain_frame.hpp"

#include "analysis/element_access.hpp"
#include "core/parallel.hpp"

namespace kontakt::analysis {

output::Frame small_strain_frame(const model::Model& model, const VecX& u, const VecX& dT,
                                 int threads) {
  const auto& elements = model.mesh.elements;
  const int n_el = model.n_elements(), n_nodes = model.n_nodes();
  output::Frame frame;
  frame.U = Eigen::Map<const MatX3>(u.data(), n_nodes, 3);
  frame.ip_offset.assign(n_el + 1, 0);
  for (int e = 0; e < n_el; ++e)
    frame.ip_offset[e + 1] = frame.ip_offset[e] + element::traits(elements[e].type).n_ip;
  const Index n_ip = frame.ip_offset.back();
  frame.S.resize(n_ip, 6);
  frame.E.resize(n_ip, 6);
  frame.ENER.resize(n_ip);
  frame.ip_volume.resize(n_ip);
  frame.EVOL.resize(n_el);
  std::vector<VecX> internal_force(n_el);
  std::vector<MatX> S_node(n_el), E_node(n_el);

  parallel_chunks(n_el, threads, [&](std::size_t begin, std::size_t end, int) {
    element::IpResults r;
    for (std::size_t e = begin; e < end; ++e) {
      const auto& el = elements[e];
      const MatX3 X = element_coords(model, el);
      const MatX3 ue = element_displacements(el, u);
      naming_element(el, [&] {
        element::recover(el.type, X, element_material(model, el), ue, element_values(el, dT), r);
      });
      const Index first = frame.ip_offset[e], count = frame.ip_offset[e + 1] - first;
      frame.S.middleRows(first, count) = r.stress;
      frame.E.middleRows(first, count) = r.strain;
      frame.ENER.segment(first, count) = r.energy_density;
      frame.ip_volume.segment(first, count) = element::ip_volumes(el.type, X);
      frame.EVOL[e] = r.volume;
      internal_force[e] = std::move(r.internal_force);
      const MatX& to_nodes = element::ip_to_node_extrapolation(el.type);
      S_node[e] = to_nodes * r.stress;
      E_node[e] = to_nodes * r.strain;
    }
  });

  // Nodal sums are serial: cheap next to the element work, and free of write conflicts.
  frame.RF = MatX3::Zero(n_nodes, 3);
  frame.S_nodal = MatX6::Zero(n_nodes, 6);
  frame.E_nodal = MatX6::Zero(n_nodes, 6);
  VecX count = VecX::Zero(n_nodes);
  for (int e = 0; e < n_el; ++e) {
    const auto& nodes = elements[e].nodes;
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      for (int c = 0; c < 3; ++c) frame.RF(nodes[a], c) += internal_force[e][3 * a + c];
      frame.S_nodal.row(nodes[a]) += S_node[e].row(a);
      frame.E_nodal.row(nodes[a]) += E_node[e].row(a);
      count[nodes[a]] += 1;
    }
  }
  for (int n = 0; n < n_nodes; ++n)
    if (count[n] > 0) {
      frame.S_nodal.row(n) /= count[n];
      frame.E_nodal.row(n) /= count[n];
    }
  return frame;
}

}  // namespace kontakt::analysis
