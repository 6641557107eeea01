// Shared helpers for the element tests: reference geometries, meshes and a dense assembler.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "element/shape_functions.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element::test {

inline constexpr ElementType kAllTypes[] = {ElementType::C3D4,  ElementType::C3D6,  ElementType::C3D8,
                                            ElementType::C3D8R, ElementType::C3D8I, ElementType::C3D10,
                                            ElementType::C3D15, ElementType::C3D20, ElementType::C3D20R};

/// Undistorted element with the reference natural coordinates as physical coordinates.
inline MatX3 reference_coordinates(Topology topo) {
  MatX3 X(node_count(topo), 3);
  for (int a = 0; a < X.rows(); ++a) X.row(a) = reference_node(topo, a).transpose();
  return X;
}

/// Reference element mapped through a smooth, orientation-preserving distortion; midside nodes
/// follow the same map so edges may curve.
inline MatX3 distorted_coordinates(Topology topo, Real amount = 0.1) {
  MatX3 X = reference_coordinates(topo);
  for (int a = 0; a < X.rows(); ++a) {
    const Vec3 p = X.row(a).transpose();
    X(a, 0) = 1.3 * p(0) + amount * p(1) * p(2) + 0.2 * p(1);
    X(a, 1) = 0.9 * p(1) + amount * p(0) * p(0) + 0.1 * p(2);
    X(a, 2) = 1.1 * p(2) + amount * p(0) * p(1) - 0.1 * p(0);
  }
  return X;
}

/// Isotropic D for engineering shear strains, written out from E and nu.
inline Mat6 elasticity_matrix_for_test(const LinearElastic& m) {
  const Real f = m.young / ((1 + m.poisson) * (1 - 2 * m.poisson));
  Mat6 D = Mat6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = f * (i == j ? 1 - m.poisson : m.poisson);
  for (int i = 3; i < 6; ++i) D(i, i) = m.young / (2 * (1 + m.poisson));
  return D;
}

/// A smooth displacement field on nodes `x`, strains of about 10 % at scale 1: large enough to
/// exercise the geometric terms of the finite-strain tangents.
inline MatX3 smooth_displacement(const MatX3& x, Real scale = 1) {
  MatX3 u(x.rows(), 3);
  for (Index a = 0; a < x.rows(); ++a)
    u.row(a) << 0.08 * x(a, 1) + 0.05 * x(a, 0) * x(a, 2), -0.06 * x(a, 2) + 0.03 * x(a, 0),
        0.1 * x(a, 0) - 0.04 * x(a, 1) * x(a, 1);
  return scale * u;
}

inline LinearElastic test_material() { return {210000.0, 0.3, 1.2e-5}; }

/// Uniform-random point inside the reference domain of a volume topology.
inline Vec3 random_point(Topology topo, std::mt19937& rng) {
  std::uniform_real_distribution<Real> U(-1.0, 1.0), P(0.0, 1.0);
  while (true) {
    Vec3 x(U(rng), U(rng), U(rng));
    switch (topo) {
      case Topology::Tet4:
      case Topology::Tet10: x = Vec3(P(rng), P(rng), P(rng)); if (x.sum() <= 1) return x; break;
      case Topology::Wedge6:
      case Topology::Wedge15: x(0) = P(rng); x(1) = P(rng); if (x(0) + x(1) <= 1) return x; break;
      case Topology::Tri3:
      case Topology::Tri6: x = Vec3(P(rng), P(rng), 0); if (x(0) + x(1) <= 1) return x; break;
      case Topology::Quad4:
      case Topology::Quad8: x(2) = 0; return x;
      default: return x;
    }
  }
}

/// A mesh: global coordinates and element connectivity (all of one type).
struct Mesh {
  ElementType type;
  MatX3 nodes;
  std::vector<std::vector<int>> elements;
};

inline MatX3 element_coordinates(const Mesh& m, const std::vector<int>& conn) {
  MatX3 X(static_cast<Index>(conn.size()), 3);
  for (std::size_t a = 0; a < conn.size(); ++a) X.row(static_cast<Index>(a)) = m.nodes.row(conn[a]);
  return X;
}

/// Dense global stiffness.
inline MatX assemble(const Mesh& m, const LinearElastic& mat) {
  const Index n = 3 * m.nodes.rows();
  MatX K = MatX::Zero(n, n);
  MatX Ke;
  for (const auto& conn : m.elements) {
    linear_stiffness(m.type, element_coordinates(m, conn), mat, VecX(), Ke);
    for (std::size_t a = 0; a < conn.size(); ++a)
      for (std::size_t b = 0; b < conn.size(); ++b)
        K.block<3, 3>(3 * conn[a], 3 * conn[b]) += Ke.block<3, 3>(3 * a, 3 * b);
  }
  return K;
}

/// Solves K u = f with u prescribed on `fixed` DOFs (values in u on entry).
inline void solve_prescribed(const MatX& K, const VecX& f, const std::vector<bool>& fixed, VecX& u) {
  std::vector<Index> fr;
  for (Index i = 0; i < K.rows(); ++i)
    if (!fixed[i]) fr.push_back(i);
  const Index m = static_cast<Index>(fr.size());
  MatX Kff(m, m);
  VecX rhs(m);
  for (Index i = 0; i < m; ++i) {
    rhs(i) = f(fr[i]);
    for (Index j = 0; j < K.rows(); ++j)
      if (fixed[j]) rhs(i) -= K(fr[i], j) * u(j);
    for (Index j = 0; j < m; ++j) Kff(i, j) = K(fr[i], fr[j]);
  }
  const VecX uf = Kff.ldlt().solve(rhs);
  for (Index i = 0; i < m; ++i) u(fr[i]) = uf(i);
}

/// Nodal forces of an element as a function of its nodal displacements (n x 3).
using ForceFunction = std::function<VecX(const MatX3& u)>;

/// Central-difference Jacobian d(forces)/du (3n x 3n, node-major) at u.
inline MatX fd_jacobian(const ForceFunction& forces, const MatX3& u, Real h = 1e-6) {
  const Index n = 3 * u.rows();
  MatX K(n, n);
  for (Index j = 0; j < n; ++j) {
    MatX3 up = u, um = u;
    up(j / 3, j % 3) += h;
    um(j / 3, j % 3) -= h;
    K.col(j) = (forces(up) - forces(um)) / (2 * h);
  }
  return K;
}

/// Taylor remainders r(t) = |f(u + t d) - f(u) - t K d| for t = 1, 1/2, 1/4 and a fixed
/// pseudo-random direction d of size `size`.
inline std::vector<Real> taylor_remainders(const ForceFunction& forces, const MatX3& u,
                                           const MatX& K, Real size) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> dist(-1, 1);
  MatX3 d(u.rows(), 3);
  for (Index k = 0; k < d.size(); ++k) d.data()[k] = size * dist(rng);
  const VecX dv = Eigen::Map<const VecX>(d.data(), d.size());
  const VecX f0 = forces(u);
  std::vector<Real> remainders;
  for (Real t : {1.0, 0.5, 0.25}) remainders.push_back((forces(u + t * d) - f0 - t * K * dv).norm());
  return remainders;
}

/// Observed orders log2(r(t) / r(t/2)) of the Taylor remainders: about 2 when K is the
/// derivative of f (and f is not linear there).
inline std::vector<Real> taylor_orders(const ForceFunction& forces, const MatX3& u, const MatX& K,
                                       Real size) {
  const std::vector<Real> r = taylor_remainders(forces, u, K, size);
  return {std::log2(r[0] / r[1]), std::log2(r[1] / r[2])};
}

}  // namespace kontakt::element::test

