#include "analysis/small_strain_frame.hpp"

#include "analysis/element_access.hpp"
#include "core/parallel.hpp"
#include "model/plane_expansion.hpp"

namespace kontakt::analysis {

output::Frame sized_frame(const model::Model& model, const VecX& u) {
  const auto& elements = model.mesh.elements;
  const int n_el = model.n_elements();
  output::Frame frame;
  frame.U = Eigen::Map<const MatX3>(u.data(), model.n_nodes(), 3);
  frame.ip_offset.assign(n_el + 1, 0);
  for (int e = 0; e < n_el; ++e)
    frame.ip_offset[e + 1] = frame.ip_offset[e] + element::traits(elements[e].type).n_ip;
  const Index n_ip = frame.ip_offset.back();
  frame.S.resize(n_ip, 6);
  frame.E.resize(n_ip, 6);
  frame.ENER.resize(n_ip);
  frame.ip_volume.resize(n_ip);
  frame.EVOL.resize(n_el);
  return frame;
}

void average_to_nodes(const model::Model& model, output::Frame& frame) {
  const int n_nodes = model.n_nodes();
  frame.S_nodal = MatX6::Zero(n_nodes, 6);
  frame.E_nodal = MatX6::Zero(n_nodes, 6);
  const bool plastic = frame.PEEQ.size() > 0;
  if (plastic) frame.PEEQ_nodal = VecX::Zero(n_nodes);
  VecX count = VecX::Zero(n_nodes);
  for (int e = 0; e < model.n_elements(); ++e) {
    const auto& el = model.mesh.elements[e];
    const Index first = frame.ip_offset[e], n = frame.ip_offset[e + 1] - first;
    const MatX& to_nodes = element::ip_to_node_extrapolation(el.type);
    const MatX S_node = to_nodes * frame.S.middleRows(first, n);
    const MatX E_node = to_nodes * frame.E.middleRows(first, n);
    const VecX PEEQ_node = plastic ? VecX(to_nodes * frame.PEEQ.segment(first, n)) : VecX();
    for (std::size_t a = 0; a < el.nodes.size(); ++a) {
      frame.S_nodal.row(el.nodes[a]) += S_node.row(a);
      frame.E_nodal.row(el.nodes[a]) += E_node.row(a);
      if (plastic) frame.PEEQ_nodal[el.nodes[a]] += PEEQ_node[static_cast<Index>(a)];
      count[el.nodes[a]] += 1;
    }
  }
  for (int n = 0; n < n_nodes; ++n)
    if (count[n] > 0) {
      frame.S_nodal.row(n) /= count[n];
      frame.E_nodal.row(n) /= count[n];
      if (plastic) frame.PEEQ_nodal[n] /= count[n];
    }
}

output::Frame small_strain_frame(const model::Model& model, const model::Step& step,
                                 const VecX& u, const VecX& dT, int threads) {
  const auto& elements = model.mesh.elements;
  const int n_el = model.n_elements();
  output::Frame frame = sized_frame(model, u);
  std::vector<VecX> internal_force(n_el);
  parallel_chunks(n_el, threads, [&](std::size_t begin, std::size_t end, int) {
    element::IpResults r;
    for (std::size_t e = begin; e < end; ++e) {
      const auto& el = elements[e];
      const MatX3 X = element_coords(model, el);
      naming_element(el, [&] {
        element::recover(el.type, X, element_material(model, el, &step), element_displacements(el, u),
                         element_values(el, dT), r);
      });
      add_initial_stress(model, el, X, r.stress, r.internal_force);
      const Index first = frame.ip_offset[e], count = frame.ip_offset[e + 1] - first;
      frame.S.middleRows(first, count) = r.stress;
      frame.E.middleRows(first, count) = r.strain;
      frame.ENER.segment(first, count) = r.energy_density;
      frame.ip_volume.segment(first, count) = element::ip_volumes(el.type, X);
      frame.EVOL[e] = r.volume;
      internal_force[e] = std::move(r.internal_force);
    }
  });
  // Nodal sums are serial: cheap next to the element work, and free of write conflicts.
  frame.RF = MatX3::Zero(model.n_nodes(), 3);
  for (int e = 0; e < n_el; ++e)
    for (std::size_t a = 0; a < elements[e].nodes.size(); ++a)
      for (int c = 0; c < 3; ++c) frame.RF(elements[e].nodes[a], c) += internal_force[e][3 * a + c];
  model::fold_to_planar_nodes(model.planar_folds, frame.U, frame.RF);
  average_to_nodes(model, frame);
  return frame;
}

}  // namespace kontakt::analysis
