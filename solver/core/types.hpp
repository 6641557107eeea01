// Scalar and fixed-size linear-algebra aliases: the one place precision is chosen.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace kontakt {

using Real = double;
using Index = std::int64_t;

using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Vec6 = Eigen::Matrix<Real, 6, 1>;
using Mat6 = Eigen::Matrix<Real, 6, 6>;
using VecX = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
/// n x 3 nodal coordinates or displacements, one row per node.
using MatX3 = Eigen::Matrix<Real, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// n x 6 symmetric tensors in Voigt order xx, yy, zz, xy, xz, yz (ccx .dat order);
/// shear strains are tensor (not engineering) components wherever they are reported.
using MatX6 = Eigen::Matrix<Real, Eigen::Dynamic, 6, Eigen::RowMajor>;

}  // namespace kontakt
