#include "contact/contact_extrapolation.hpp"

#include <Eigen/QR>
#include <map>

#include "core/error.hpp"
#include "element/element_type.hpp"

namespace kontakt::contact {

namespace {

using element::Topology;
using Method = ExtrapolationMethod;
using RowVec = Eigen::Matrix<Real, 1, Eigen::Dynamic>;

/// Columns extrapolated by contact_nodal_values: CPRESS, COPEN, CSHEAR1, CSHEAR2, CSLIP1,
/// CSLIP2 and the share of sticking points.
constexpr int kFields = 7;

/// Pivots below this fraction of the largest make a fit undetermined by its points.
constexpr Real kRankTolerance = 1e-8;

bool is_triangle(Topology face) { return face == Topology::Tri3 || face == Topology::Tri6; }
int corner_count(Topology face) { return is_triangle(face) ? 3 : 4; }
Topology corner_topology(Topology face) {
  return is_triangle(face) ? Topology::Tri3 : Topology::Quad4;
}

/// The functions a fit combines, at local point `xi`: {1}, {1, xi, eta} or the corner shape
/// functions (whose coefficients are the corner values themselves).
RowVec basis(Method method, Topology face, const Vec2& xi) {
  switch (method) {
    case Method::Constant: return RowVec::Ones(1);
    case Method::Plane: {
      RowVec b(3);
      b << 1, xi(0), xi(1);
      return b;
    }
    case Method::ShapeFunctions:
    case Method::LeastSquares: break;
  }
  element::ShapeVec N;
  element::ShapeGrad dN;
  element::shape_functions(corner_topology(face), Vec3(xi(0), xi(1), 0), N, dN);
  return N.transpose();
}

Method simpler(Method method) {
  return method == Method::Plane ? Method::Constant : Method::Plane;
}

}  // namespace

ExtrapolationMethod extrapolation_method(Topology face, int n_points) {
  KONTAKT_REQUIRE(dimension(face) == 2, "extrapolation_method: not a face topology");
  KONTAKT_REQUIRE(n_points >= 1, "extrapolation_method: no points");
  const int corners = corner_count(face);
  if (n_points < 3) return Method::Constant;
  if (n_points < corners) return Method::Plane;
  if (n_points == corners) return Method::ShapeFunctions;
  return Method::LeastSquares;
}

MatX fit_corner_values(Topology face, ExtrapolationMethod method, const std::vector<Vec2>& xi,
                       const MatX& values) {
  const auto n = static_cast<Index>(xi.size());
  KONTAKT_REQUIRE(n >= 1 && values.rows() == n, "fit_corner_values: one value row per point");
  const int corners = corner_count(face);
  for (;;) {
    const auto m = basis(method, face, xi.front()).size();
    MatX design(n, m);
    for (Index j = 0; j < n; ++j)
      design.row(j) = basis(method, face, xi[static_cast<std::size_t>(j)]);
    Eigen::ColPivHouseholderQR<MatX> qr(design);
    qr.setThreshold(kRankTolerance);
    if (qr.rank() == m) {
      // Square systems are solved exactly (interpolation), taller ones in least squares.
      const MatX coefficients = qr.solve(values);
      MatX at_corners(corners, m);
      for (int k = 0; k < corners; ++k) {
        const Vec3 corner = element::reference_node(corner_topology(face), k);
        at_corners.row(k) = basis(method, face, Vec2(corner(0), corner(1)));
      }
      return at_corners * coefficients;
    }
    method = simpler(method);  // the constant fit is determined by any one point
  }
}

MatX extrapolate_face(Topology face, const std::vector<Vec2>& xi, const MatX& values) {
  const MatX fitted =
      fit_corner_values(face, extrapolation_method(face, static_cast<int>(xi.size())), xi, values);
  const int corners = corner_count(face);
  MatX nodal(element::node_count(face), values.cols());
  for (Index f = 0; f < values.cols(); ++f) {
    // Thesis §4.3.2: few points in one corner of a face must not produce peaks at the others.
    const Real low = values.col(f).minCoeff(), high = values.col(f).maxCoeff();
    nodal.col(f).head(corners) = fitted.col(f).cwiseMax(low).cwiseMin(high);
  }
  // Midside node c + e sits on the edge from corner e to corner e + 1 (ccx face order).
  for (int e = 0; e + corners < nodal.rows(); ++e)
    nodal.row(corners + e) = 0.5 * (nodal.row(e) + nodal.row((e + 1) % corners));
  return nodal;
}

NodalAverage average_over_faces(int n_nodes, int n_fields,
                                const std::vector<FaceNodeValues>& faces,
                                const std::vector<bool>& outside_master) {
  NodalAverage average{MatX::Zero(n_nodes, n_fields),
                       std::vector<int>(static_cast<std::size_t>(n_nodes), 0)};
  for (const FaceNodeValues& face : faces) {
    KONTAKT_REQUIRE(face.values.rows() == static_cast<Index>(face.nodes.size()) &&
                        face.values.cols() == n_fields,
                    "average_over_faces: one value row per face node");
    for (std::size_t i = 0; i < face.nodes.size(); ++i) {
      const int node = face.nodes[i];
      if (!outside_master.empty() && outside_master[static_cast<std::size_t>(node)]) continue;
      average.values.row(node) += face.values.row(static_cast<Index>(i));
      ++average.n_faces[static_cast<std::size_t>(node)];
    }
  }
  for (int node = 0; node < n_nodes; ++node)
    if (const int n = average.n_faces[static_cast<std::size_t>(node)]; n > 1)
      average.values.row(node) /= n;
  return average;
}

output::ContactNodal contact_nodal_values(const model::Model& model,
                                          const std::vector<output::ContactPointRecord>& points,
                                          const std::vector<bool>& outside_master) {
  const auto fields_of = [](const output::ContactPointRecord& p) {
    RowVec row(kFields);
    row << p.pressure, p.clearance, p.shear(0), p.shear(1), p.slip(0), p.slip(1),
        p.sticking ? 1.0 : 0.0;
    return row;
  };
  std::vector<FaceNodeValues> faces;
  std::map<std::pair<int, int>, std::vector<const output::ContactPointRecord*>> by_face;
  for (const output::ContactPointRecord& p : points) {
    if (!p.active) continue;
    if (p.slave_node >= 0) {
      faces.push_back(FaceNodeValues{{p.slave_node}, fields_of(p)});  // a one-node "face"
    } else {
      by_face[{p.slave_element, p.slave_face}].push_back(&p);
    }
  }
  for (const auto& [key, face_points] : by_face) {
    const model::Element& element = model.mesh.elements[static_cast<std::size_t>(key.first)];
    std::vector<Vec2> xi;
    MatX values(static_cast<Index>(face_points.size()), kFields);
    for (std::size_t j = 0; j < face_points.size(); ++j) {
      xi.push_back(face_points[j]->xi);
      values.row(static_cast<Index>(j)) = fields_of(*face_points[j]);
    }
    FaceNodeValues face;
    for (int local : element::face_nodes(element.type, key.second))
      face.nodes.push_back(element.nodes[static_cast<std::size_t>(local)]);
    face.values = extrapolate_face(element::face_topology(element.type, key.second), xi, values);
    faces.push_back(std::move(face));
  }
  const NodalAverage average = average_over_faces(model.n_nodes(), kFields, faces, outside_master);
  output::ContactNodal nodal;
  nodal.CPRESS = average.values.col(0);
  nodal.COPEN = average.values.col(1);
  nodal.CSHEAR = average.values.middleCols(2, 2);
  nodal.CSLIP = average.values.middleCols(4, 2);
  nodal.status = VecX::Zero(model.n_nodes());
  for (int node = 0; node < model.n_nodes(); ++node)
    if (average.n_faces[static_cast<std::size_t>(node)] > 0)
      nodal.status(node) = average.values(node, 6) >= 0.5 ? 1 : 2;
  return nodal;
}

}  // namespace kontakt::contact
