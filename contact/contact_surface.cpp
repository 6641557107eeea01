#include "contact/contact_surface.hpp"

#include <algorithm>
#include <map>

#include "element/quadrature.hpp"

namespace kontakt::contact {

ContactSurface make_contact_surface(const model::Model& model, const model::Surface& surface) {
  ContactSurface s;
  s.name = surface.name;
  if (surface.kind == model::Surface::Kind::Nodes) {
    s.nodes = surface.nodes;
  } else {
    for (const auto& ef : surface.faces) {
      const auto& el = model.mesh.elements[ef.element];
      SurfaceFace f;
      f.element = ef.element;
      f.face = ef.face;
      f.element_type = el.type;
      f.topo = element::face_topology(el.type, ef.face);
      for (int local : element::face_nodes(el.type, ef.face)) f.nodes.push_back(el.nodes[local]);
      s.nodes.insert(s.nodes.end(), f.nodes.begin(), f.nodes.end());
      s.faces.push_back(std::move(f));
    }
  }
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  return s;
}

std::vector<SurfaceFace> exterior_faces_at(const model::Model& model, const std::vector<int>& nodes) {
  std::vector<char> wanted(model.n_nodes(), 0);
  for (int n : nodes) wanted[n] = 1;
  // Faces of the elements at those nodes, keyed by their sorted corner nodes: a face met twice
  // is shared by two elements, hence interior.
  std::map<std::vector<int>, std::pair<int, SurfaceFace>> faces;
  for (std::size_t e = 0; e < model.mesh.elements.size(); ++e) {
    const auto& el = model.mesh.elements[e];
    const int n_faces = element::traits(el.type).n_faces;
    // Faces 1 and 2 of a 2D element's expansion are the front and back of its layer, no
    // boundary of the 2D body: its edges (faces 3 on) carry the area.
    const int first_face = el.planar == model::Planar::None ? 1 : 3;
    for (int f = first_face; f <= n_faces; ++f) {
      SurfaceFace sf{static_cast<int>(e), f, element::face_topology(el.type, f), el.type, {}};
      bool touches = false;
      for (int local : element::face_nodes(el.type, f)) {
        sf.nodes.push_back(el.nodes[local]);
        touches |= wanted[el.nodes[local]] != 0;
      }
      if (!touches) continue;
      std::vector<int> key(sf.nodes.begin(), sf.nodes.begin() + (is_triangle(sf.topo) ? 3 : 4));
      std::sort(key.begin(), key.end());
      auto [it, fresh] = faces.try_emplace(key, 0, sf);
      ++it->second.first;
    }
  }
  std::vector<SurfaceFace> out;
  for (auto& [key, counted] : faces)
    if (counted.first == 1) out.push_back(std::move(counted.second));
  return out;
}

FaceGeometry face_geometry(const SurfaceFace& face, const MatX3& coords, const VecX& u) {
  FaceGeometry g{face.topo, FaceCoords(face.nodes.size(), 3)};
  for (std::size_t i = 0; i < face.nodes.size(); ++i) {
    const int n = face.nodes[i];
    g.x.row(i) = coords.row(n) + u.segment<3>(3 * n).transpose();
  }
  return g;
}

Box face_box(const FaceGeometry& face) {
  Box b;
  for (int i = 0; i < face.x.rows(); ++i) b.add(face.x.row(i).transpose());
  return b;
}

Real face_size(const FaceGeometry& face) {
  const int nc = is_triangle(face.topo) ? 3 : 4;
  Real size = 0;
  for (int i = 0; i < nc; ++i) size = std::max(size, (face.x.row((i + 1) % nc) - face.x.row(i)).norm());
  return size;
}

Real face_area(const FaceGeometry& face) {
  Real area = 0;
  for (const auto& q : element::face_rule(face.topo))
    area += q.weight * surface_point(face, Vec2(q.xi(0), q.xi(1))).jacobian;
  return area;
}

}  // namespace kontakt::contact
