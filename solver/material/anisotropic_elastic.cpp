#include "material/anisotropic_elastic.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <stdexcept>

namespace kontakt::material {

namespace {

// Voigt position of tensor index pairs: xx yy zz xy xz yz.
constexpr int kRow[6] = {0, 1, 2, 0, 0, 1};
constexpr int kCol[6] = {0, 1, 2, 1, 2, 2};

Mat3 symmetric_tensor(const Vec6& v) {
  Mat3 t;
  t << v(0), v(3), v(4), v(3), v(1), v(5), v(4), v(5), v(2);
  return t;
}

}  // namespace

Mat6 anisotropic_stiffness(const AnisotropicConstants& d) {
  Mat6 D;
  std::size_t k = 0;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i <= j; ++i) D(i, j) = D(j, i) = d[k++];
  return D;
}

AnisotropicConstants from_orthotropic(const OrthotropicConstants& d) {
  AnisotropicConstants a{};
  // Positions of D1111 .. D3333, D1212, D1313, D2323 in the column-wise upper triangle.
  constexpr std::size_t kAt[9] = {0, 1, 2, 3, 4, 5, 9, 14, 20};
  for (std::size_t i = 0; i < 9; ++i) a[kAt[i]] = d[i];
  return a;
}

AnisotropicConstants from_engineering(const EngineeringConstants& c) {
  const Real E1 = c[0], E2 = c[1], E3 = c[2], nu12 = c[3], nu13 = c[4], nu23 = c[5];
  for (std::size_t i : {0u, 1u, 2u, 6u, 7u, 8u})
    if (!(c[i] > 0)) throw std::invalid_argument("the moduli E1, E2, E3, G12, G13, G23 must be positive");
  Mat3 compliance;
  compliance << 1 / E1, -nu12 / E1, -nu13 / E1,  //
      -nu12 / E1, 1 / E2, -nu23 / E2,            //
      -nu13 / E1, -nu23 / E2, 1 / E3;
  const Eigen::FullPivLU<Mat3> lu(compliance);
  if (!lu.isInvertible())
    throw std::invalid_argument("the engineering constants give a singular compliance");
  const Mat3 normal = lu.inverse();
  return {normal(0, 0), normal(0, 1), normal(1, 1), normal(0, 2), normal(1, 2), normal(2, 2),
          0, 0, 0, c[6], 0, 0, 0, 0, c[7], 0, 0, 0, 0, 0, c[8]};
}

bool is_positive_definite(const Mat6& D) {
  return Eigen::LLT<Mat6>(D).info() == Eigen::Success;
}

Mat6 rotate_stiffness(const Mat6& D_local, const Mat3& R) {
  // Column j of T: the local engineering strain of the global unit engineering strain j.
  Mat6 T;
  for (int j = 0; j < 6; ++j) {
    Vec6 e = Vec6::Zero();
    e(j) = j < 3 ? 1 : 0.5;  // tensor components of a unit engineering strain
    const Mat3 local = R.transpose() * symmetric_tensor(e) * R;
    for (int i = 0; i < 6; ++i) T(i, j) = (i < 3 ? 1 : 2) * local(kRow[i], kCol[i]);
  }
  return T.transpose() * D_local * T;
}

Vec6 stress_to_local(const Vec6& stress, const Mat3& R) {
  const Mat3 local = R.transpose() * symmetric_tensor(stress) * R;
  Vec6 v;
  for (int i = 0; i < 6; ++i) v(i) = local(kRow[i], kCol[i]);
  return v;
}

}  // namespace kontakt::material
