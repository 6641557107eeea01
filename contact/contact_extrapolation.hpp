// Contact values from the integration points to the nodes (thesis §4.3.2-4.3.3, table 2), for
// the results file: per slave face a fit chosen by the number of points, evaluated at the
// corners and clamped to the points' range, midside nodes as the mean of their corners, then
// the mean over the slave faces at each node. Only the active points of a converged frame
// enter, as ccx extrapolates the values of its contact elements. Pure functions.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "element/shape_functions.hpp"
#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::contact {

/// Table 2 of the thesis: how the point values of one slave face become corner values.
enum class ExtrapolationMethod {
  Constant,        ///< fewer than 3 points: their mean at every corner
  Plane,           ///< quadrilateral, 3 points: the plane a + b xi + c eta through them
  ShapeFunctions,  ///< as many points as corners: interpolation with the corner shape functions
  LeastSquares,    ///< more points than corners: least-squares fit of the corner shape functions
};

/// The method table 2 assigns to `n_points` (>= 1) points on a face of topology `face`
/// (Tri3, Tri6, Quad4 or Quad8; quadratic faces are fitted through their corners).
ExtrapolationMethod extrapolation_method(element::Topology face, int n_points);

/// Corner values (3 or 4 rows, one column per field) of the fit `method` to the points' values
/// (`values`: one row per point; `xi`: the points' local face coordinates), not clamped. When
/// the points do not determine that fit (all on one line, or a bilinear fit of points on the
/// axes), the next simpler one is used: least squares and shape functions fall back to the
/// plane, the plane to the constant.
MatX fit_corner_values(element::Topology face, ExtrapolationMethod method,
                       const std::vector<Vec2>& xi, const MatX& values);

/// Values at all nodes of one slave face (node_count(face) rows, in face node order: corners,
/// then midside nodes): corners by table 2, clamped per field to the [min, max] of the points'
/// values; each midside node the mean of the two corners of its edge. Needs one point or more.
MatX extrapolate_face(element::Topology face, const std::vector<Vec2>& xi, const MatX& values);

/// The extrapolated values of one slave face at its nodes.
struct FaceNodeValues {
  std::vector<int> nodes;  ///< internal node indices, face node order
  MatX values;             ///< one row per node of `nodes`
};

/// Values at the model's nodes: per node the mean over the faces that give it a value.
struct NodalAverage {
  MatX values;                ///< n_nodes rows; zero where no face gives a value
  std::vector<int> n_faces;   ///< faces that contributed, per node (0: no contact value)
};

/// Averages `faces` (all with the same number of columns, `n_fields`) at the nodes. Nodes
/// with `outside_master[node]` set are left out (thesis §4.3.2: a node beyond the border of
/// the master surface is not extrapolated); an empty `outside_master` leaves none out.
NodalAverage average_over_faces(int n_nodes, int n_fields,
                                const std::vector<FaceNodeValues>& faces,
                                const std::vector<bool>& outside_master);

/// CPRESS, COPEN, CSHEAR, CSLIP and CSTATUS at the model's nodes from the contact points of a
/// converged frame; inactive points are ignored. Surface-to-surface points are extrapolated
/// per slave face and averaged over the faces (the functions above); node-to-surface points
/// give their slave node's values directly (the mean, if several pairs share the node). COPEN
/// keeps ccx's clearance sign (negative = penetration). CSTATUS is 0 where no contact value
/// arrives, otherwise 1 (stick) where the share of sticking points, treated like the other
/// fields, is at least one half, else 2 (slip). `outside_master` as for average_over_faces.
output::ContactNodal contact_nodal_values(const model::Model& model,
                                          const std::vector<output::ContactPointRecord>& points,
                                          const std::vector<bool>& outside_master);

}  // namespace kontakt::contact
