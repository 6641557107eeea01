// Contact surfaces built from the deck's element-face surfaces (or node sets, for the slave side
// of node-to-surface pairs): the faces with their topology and nodes, and their geometry in a
// given configuration.
#pragma once

#include <vector>

#include "contact/aabb_tree.hpp"
#include "contact/closest_point.hpp"
#include "model/model.hpp"

namespace kontakt::contact {

struct SurfaceFace {
  int element = 0;          ///< internal element index
  int face = 1;             ///< 1-based ccx face number
  element::Topology topo = element::Topology::Quad4;
  element::ElementType element_type = element::ElementType::C3D8;
  std::vector<int> nodes;   ///< internal node indices, face order (corners, then midsides)
};

struct ContactSurface {
  std::string name;
  std::vector<SurfaceFace> faces;
  std::vector<int> nodes;   ///< every node of the surface, ascending
};

/// The faces of an element-face surface; for a node surface only `nodes` is filled.
ContactSurface make_contact_surface(const model::Model& model, const model::Surface& surface);

/// The exterior faces (faces of one element only) that contain one of `nodes`: where a
/// node-based slave surface takes its nodal areas from, as ccx does.
std::vector<SurfaceFace> exterior_faces_at(const model::Model& model, const std::vector<int>& nodes);

/// Current coordinates of the nodes of `face` (reference coordinates + displacements).
FaceGeometry face_geometry(const SurfaceFace& face, const MatX3& coords, const VecX& u);

Box face_box(const FaceGeometry& face);

/// Longest edge between consecutive corners: the length scale of a face.
Real face_size(const FaceGeometry& face);

/// Face area from its pressure rule.
Real face_area(const FaceGeometry& face);

}  // namespace kontakt::contact
