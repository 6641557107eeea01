#include "contact/contact_surface.hpp"

#include <algorithm>

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
