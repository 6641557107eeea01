// C3D8I: trilinear brick enriched with the Wilson-Taylor incompatible modes 1-xi^2, 1-eta^2,
// 1-zeta^2 (9 internal DOFs). Their derivatives use the centroid Jacobian scaled by
// det(J0)/det(J) (Taylor, Beresford & Wilson 1976) so the patch test is passed; the internal
// DOFs are condensed statically on the element.
#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/error.hpp"
#include "element/quadrature.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {
namespace {

using Mat24 = Eigen::Matrix<Real, 24, 24>;
using Mat24x9 = Eigen::Matrix<Real, 24, 9>;
using Mat9 = Eigen::Matrix<Real, 9, 9>;
using Vec9 = Eigen::Matrix<Real, 9, 1>;
using Vec24 = Eigen::Matrix<Real, 24, 1>;
using GMatrix = Eigen::Matrix<Real, 6, 9>;

struct CentroidFrame {
  Mat3 inv_jt;  ///< J0^{-T}
  Real det = 0;
};

CentroidFrame centroid_frame(const MatX3& X) {
  KONTAKT_REQUIRE(X.rows() == 8, "C3D8I: needs 8 nodes");
  const PointGeometry g0 = point_geometry(Topology::Hex8, X, Vec3::Zero());
  return {g0.J.inverse().transpose(), g0.detJ};
}

// Physical gradients of the three modes at natural point xi (3 x 3, one row per mode): the
// natural gradients mapped with the centroid Jacobian as shape-function gradients are,
// dphi J0^-T (point_geometry), scaled by det(J0)/det(J).
ShapeGrad mode_gradients(const CentroidFrame& c, const Vec3& xi, Real detJ) {
  ShapeGrad dphi = ShapeGrad::Zero(3, 3);
  for (int m = 0; m < 3; ++m) dphi(m, m) = -2 * xi(m);
  return (c.det / detJ) * (dphi * c.inv_jt);
}

// Strain matrix of the incompatible modes at natural point xi.
GMatrix g_matrix(const CentroidFrame& c, const Vec3& xi, Real detJ) {
  BMatrix G;
  b_matrix(mode_gradients(c, xi, detJ), G);
  return G;
}

// Integrated blocks: Kuu, Kua, Kaa, and the thermal loads fu, fa.
struct Blocks {
  Mat24 Kuu = Mat24::Zero();
  Mat24x9 Kua = Mat24x9::Zero();
  Mat9 Kaa = Mat9::Zero();
  Vec24 fu = Vec24::Zero();
  Vec9 fa = Vec9::Zero();
};

Blocks integrate(const MatX3& X, const ThermoElastic& mat, const VecX& dT) {
  const CentroidFrame c = centroid_frame(X);
  Blocks k;
  BMatrix B;
  for (const auto& q : volume_rule(ElementType::C3D8I)) {
    const PointGeometry g = point_geometry(Topology::Hex8, X, q.xi);
    b_matrix(g.dNdx, B);
    const GMatrix G = g_matrix(c, q.xi, g.detJ);
    const Real dv = q.weight * g.detJ;
    const PointElastic m = point_material(mat, ElementType::C3D8I, q.xi, g.N, dT);
    const Mat6 D = elasticity_matrix(m);
    k.Kuu.noalias() += dv * (B.transpose() * D * B);
    k.Kua.noalias() += dv * (B.transpose() * D * G);
    k.Kaa.noalias() += dv * (G.transpose() * D * G);
    if (dT.size() == 8) {
      const Vec6 s_th = D * thermal_strain(m);
      k.fu.noalias() += dv * (B.transpose() * s_th);
      k.fa.noalias() += dv * (G.transpose() * s_th);
    }
  }
  return k;
}

}  // namespace

void incompatible_stiffness(const MatX3& X, const ThermoElastic& mat, const VecX& dT, MatX& K) {
  const Blocks k = integrate(X, mat, dT.size() == 8 ? dT : VecX());
  const Eigen::PartialPivLU<Mat9> lu(k.Kaa);
  K = k.Kuu - k.Kua * lu.solve(k.Kua.transpose());
  K = 0.5 * (K + K.transpose()).eval();
}

void incompatible_thermal_load(const MatX3& X, const ThermoElastic& mat, const VecX& dT, VecX& f) {
  KONTAKT_REQUIRE(dT.size() == 8, "thermal_load: wrong number of temperatures");
  const Blocks k = integrate(X, mat, dT);
  const Eigen::PartialPivLU<Mat9> lu(k.Kaa);
  f = k.fu - k.Kua * lu.solve(k.fa);
}

void incompatible_strains(const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                          const VecX& dT, Eigen::Matrix<Real, 8, 6>& strains) {
  const Blocks k = integrate(X, mat, dT);
  const Eigen::Map<const Vec24> ue(u.data());
  const Vec9 alpha = Eigen::PartialPivLU<Mat9>(k.Kaa).solve(k.fa - k.Kua.transpose() * ue);
  const CentroidFrame c = centroid_frame(X);
  BMatrix B;
  const auto rule = volume_rule(ElementType::C3D8I);
  for (int p = 0; p < 8; ++p) {
    const PointGeometry g = point_geometry(Topology::Hex8, X, rule[p].xi);
    b_matrix(g.dNdx, B);
    strains.row(p) = (B * ue + g_matrix(c, rule[p].xi, g.detJ) * alpha).transpose();
  }
}

std::vector<KernelPoint> incompatible_kernel_points(const MatX3& X, const ThermoElastic& mat,
                                                   const VecX& dT) {
  const CentroidFrame c = centroid_frame(X);
  const auto rule = volume_rule(ElementType::C3D8I);
  std::vector<KernelPoint> points(rule.size());
  for (std::size_t k = 0; k < rule.size(); ++k) {
    const PointGeometry g = point_geometry(Topology::Hex8, X, rule[k].xi);
    KernelPoint& p = points[k];
    p.dNdX.resize(11, 3);
    p.dNdX.topRows(8) = g.dNdx;
    p.dNdX.bottomRows(3) = mode_gradients(c, rule[k].xi, g.detJ);
    p.dv = rule[k].weight * g.detJ;
    p.material = point_material(mat, ElementType::C3D8I, rule[k].xi, g.N, dT);
  }
  return points;
}

Mat3 incompatible_frame_rotation(const MatX3& X, const MatX3& u) {
  const Mat3 F = deformation_gradient(point_geometry(Topology::Hex8, X, Vec3::Zero()).dNdx, u);
  const Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) *= -1;  // proper rotation
  return U * svd.matrixV().transpose();
}

}  // namespace kontakt::element
