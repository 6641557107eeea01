// Tests for the Ramberg-Osgood deformation plasticity law (solver/material/
// deformation_plasticity): a point of ccx 2.20's own solution, the tangent against the stress
// by central differences and a Taylor test, the small-strain limit, objectivity, the refusals.
#include "material/deformation_plasticity.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::material {
namespace {

/// beampl's constants (the ccx suite deck).
RambergOsgood beampl() { return {190000., 0.34, 900., 12., 0.45}; }

/// The symmetric stretch of a Green-Lagrange strain with engineering shear: S depends on C only.
Mat3 stretch(const Vec6& e) {
  Mat3 E;
  E << e(0), e(3) / 2, e(4) / 2, e(3) / 2, e(1), e(5) / 2, e(4) / 2, e(5) / 2, e(2);
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(Mat3::Identity() + 2 * E);
  return eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().asDiagonal() *
         eig.eigenvectors().transpose();
}

DeformationPlasticityResponse at(const Vec6& e) { return deformation_plasticity(beampl(), stretch(e)); }

Mat3 cauchy(const DeformationPlasticityResponse& r, const Mat3& F) {
  Mat3 S;
  S << r.stress(0), r.stress(3), r.stress(4), r.stress(3), r.stress(1), r.stress(5), r.stress(4),
      r.stress(5), r.stress(2);
  return F * S * F.transpose() / F.determinant();
}

TEST(DeformationPlasticity, ReproducesCcxOnAStretchedCube) {
  // ccx 2.20, one C3D8 cube stretched by 10 % under NLGEOM (rollers, free sides): its lateral
  // stretch 1 - 3.985103e-2 gives sigma_xx 1216.487, sigma_yy = sigma_zz -1.403326.
  const Mat3 F = Vec3(1.1, 1 - 3.985103e-2, 1 - 3.985103e-2).asDiagonal();
  const DeformationPlasticityResponse r = deformation_plasticity(beampl(), F);
  const Mat3 sigma = cauchy(r, F);
  EXPECT_NEAR(sigma(0, 0), 1216.487, 2e-3);
  EXPECT_NEAR(sigma(1, 1), -1.403326, 2e-3);
  EXPECT_NEAR(sigma(2, 2), -1.403326, 2e-3);
}

TEST(DeformationPlasticity, TangentIsTheDerivativeOfTheStressAndConvergesQuadratically) {
  Vec6 e;
  e << 0.08, -0.03, 0.05, 0.06, -0.04, 0.03;  // far into the plastic range
  const DeformationPlasticityResponse r = at(e);
  const Real h = 1e-7;
  Mat6 fd;
  for (int b = 0; b < 6; ++b) {
    Vec6 p = e, m = e;
    p(b) += h;
    m(b) -= h;
    fd.col(b) = (at(p).stress - at(m).stress) / (2 * h);
  }
  EXPECT_LT((fd - r.tangent).norm(), 1e-6 * r.tangent.norm());
  Vec6 d;
  d << 0.3, -0.2, 0.5, 0.4, 0.1, -0.6;
  std::vector<Real> errors;
  for (Real t : {1e-3, 5e-4, 2.5e-4})
    errors.push_back((at(e + t * d).stress - r.stress - t * r.tangent * d).norm());
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_GT(std::log(errors[k - 1] / errors[k]) / std::log(2.0), 1.9);
}

TEST(DeformationPlasticity, AtRestTheTangentIsLinearElasticity) {
  const DeformationPlasticityResponse r = deformation_plasticity(beampl(), Mat3::Identity());
  EXPECT_LT(r.stress.norm(), 1e-12);
  EXPECT_LT((r.tangent - isotropic_elastic_stiffness(190000., 0.34)).norm(), 1e-10 * r.tangent.norm());
}

TEST(DeformationPlasticity, TheCauchyStressTurnsWithTheBody) {
  Vec6 e;
  e << 0.05, 0.01, -0.02, 0.03, 0.0, 0.01;
  const Mat3 U = stretch(e);
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const DeformationPlasticityResponse plain = deformation_plasticity(beampl(), U);
  const DeformationPlasticityResponse turned = deformation_plasticity(beampl(), R * U);
  EXPECT_LT((plain.stress - turned.stress).norm(), 1e-9 * plain.stress.norm());
  EXPECT_LT((cauchy(turned, R * U) - R * cauchy(plain, U) * R.transpose()).norm(),
            1e-9 * cauchy(plain, U).norm());
}

TEST(DeformationPlasticity, RefusesConstantsWithoutALawAndAnInvertedElement) {
  const Mat3 F = Mat3::Identity();
  EXPECT_THROW(deformation_plasticity({0., 0.3, 900., 12., 0.45}, F), SolverError);
  EXPECT_THROW(deformation_plasticity({190000., 0.5, 900., 12., 0.45}, F), SolverError);
  EXPECT_THROW(deformation_plasticity({190000., 0.3, 0., 12., 0.45}, F), SolverError);
  EXPECT_THROW(deformation_plasticity({190000., 0.3, 900., 0.5, 0.45}, F), SolverError);
  EXPECT_THROW(deformation_plasticity(beampl(), Vec3(1, 1, -1).asDiagonal()), SolverError);
}

}  // namespace
}  // namespace kontakt::material
