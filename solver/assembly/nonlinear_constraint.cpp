#include "assembly/nonlinear_constraint.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace kontakt::assembly {

namespace {

using model::NonlinearConstraint;
using Dual = Eigen::AutoDiffScalar<VecX>;
template <class S>
using V3 = Eigen::Matrix<S, 3, 1>;

/// R(theta) v = v + a theta x v + b theta x (theta x v) with a = sin t / t and
/// b = (1 - cos t) / t^2 (t = |theta|); their series below t^2 = 1e-8, where the closed forms
/// lose digits (and a derivative through sqrt would divide by zero at t = 0).
template <class S>
V3<S> rotated(const V3<S>& theta, const V3<S>& v) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S t2 = theta.dot(theta);
  S a, b;
  if (t2 < 1e-8) {
    a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0;
    b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
  } else {
    const S t = sqrt(t2);
    a = sin(t) / t;
    b = (1.0 - cos(t)) / t2;
  }
  const V3<S> txv = theta.cross(v);
  return v + a * txv + b * theta.cross(txv);
}

template <class S>
S residual(const NonlinearConstraint& c, const std::vector<Vec3>& X, const std::vector<V3<S>>& u) {
  const int j = c.component;
  auto x = [&](int i) -> V3<S> { return X[i].template cast<S>() + u[i]; };
  switch (c.kind) {
    case NonlinearConstraint::Kind::Rigid: {  // nodes p, ref, rot
      const V3<S> arm = (X[0] - X[1]).template cast<S>();
      return x(0)[j] - x(1)[j] - rotated<S>(u[2], arm)[j];
    }
    case NonlinearConstraint::Kind::Plane: {  // nodes p, a, b, c
      const V3<S> a = x(1);
      return (x(0) - a).dot((x(2) - a).cross(x(3) - a));
    }
    case NonlinearConstraint::Kind::Straight: {  // nodes p, a, b
      const int k = c.pivot;
      const V3<S> e = x(0) - x(1), t = x(2) - x(1);
      return e[j] * t[k] - e[k] * t[j];
    }
    case NonlinearConstraint::Kind::MeanRotation: {  // nodes n_1 .. n_N, e
      // sum_i asin(lambda_i) = N gamma, lambda_i the sine of node i's rotation about the axis
      // a, both of its positions relative to the set's centre and projected on a's normal
      // plane (the displacement relative to the set's mean displacement).
      using std::asin;
      const std::size_t n = X.size() - 1;
      const Vec3 a = X[n].normalized();
      const Mat3 P = Mat3::Identity() - a * a.transpose();
      Vec3 centre = Vec3::Zero();
      V3<S> mean = V3<S>::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        centre += X[i] / static_cast<Real>(n);
        mean += u[i] / static_cast<Real>(n);
      }
      S sum(0.0);
      for (std::size_t i = 0; i < n; ++i) {
        const V3<S> b = (P * (X[i] - centre)).template cast<S>();
        const V3<S> w = b + P.template cast<S>() * (u[i] - mean);
        sum += asin(b.cross(w).dot(a.template cast<S>()) / (b.norm() * w.norm()));
      }
      return sum - static_cast<Real>(n) * u[n][0];
    }
    case NonlinearConstraint::Kind::Distance:  // nodes a, b
      return (x(0) - x(1)).squaredNorm() - c.distance * c.distance;
  }
  return S(0);
}

}  // namespace

Vec3 rotate(const Vec3& theta, const Vec3& v) { return rotated<Real>(theta, v); }

std::vector<ConstraintDof> constraint_dofs(const NonlinearConstraint& c) {
  const auto& n = c.nodes;
  std::vector<ConstraintDof> out{{n[0], c.component}};
  auto all_of = [&](int node) {
    for (int k = 0; k < 3; ++k) out.push_back({node, k});
  };
  switch (c.kind) {
    case NonlinearConstraint::Kind::Rigid:
      all_of(n[1]);
      all_of(n[2]);
      break;
    case NonlinearConstraint::Kind::Plane:
      for (int k = 0; k < 3; ++k)
        if (k != c.component) out.push_back({n[0], k});
      for (int i = 1; i < 4; ++i) all_of(n[i]);
      break;
    case NonlinearConstraint::Kind::Distance:
      for (int k = 0; k < 3; ++k)
        if (k != c.component) out.push_back({n[0], k});
      all_of(n[1]);
      break;
    case NonlinearConstraint::Kind::MeanRotation:
      for (int k = 0; k < 3; ++k)
        if (k != c.component) out.push_back({n[0], k});
      for (std::size_t i = 1; i + 1 < n.size(); ++i) all_of(n[i]);
      out.push_back({n.back(), 0});
      break;
    case NonlinearConstraint::Kind::Straight:
      out.push_back({n[0], c.pivot});
      for (int i = 1; i < 3; ++i) {
        out.push_back({n[i], c.component});
        out.push_back({n[i], c.pivot});
      }
      break;
  }
  return out;
}

Real constraint_value(const NonlinearConstraint& c, const MatX3& coords, const VecX& u,
                      VecX* gradient) {
  const std::size_t n = c.nodes.size();
  std::vector<Vec3> X(n);
  for (std::size_t i = 0; i < n; ++i) X[i] = coords.row(c.nodes[i]).transpose();
  auto displacement = [&](std::size_t i) -> Vec3 { return u.segment<3>(3 * c.nodes[i]); };
  if (!gradient) {
    std::vector<V3<Real>> ur(n);
    for (std::size_t i = 0; i < n; ++i) ur[i] = displacement(i);
    return residual<Real>(c, X, ur);
  }
  const std::vector<ConstraintDof> dofs = constraint_dofs(c);
  const int m = static_cast<int>(dofs.size());
  std::vector<V3<Dual>> ud(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) ud[i][k] = Dual(displacement(i)[k], VecX::Zero(m));
  for (int q = 0; q < m; ++q)
    for (std::size_t i = 0; i < n; ++i)
      if (c.nodes[i] == dofs[q].node) ud[i][dofs[q].component].derivatives()[q] = 1;
  const Dual g = residual<Dual>(c, X, ud);
  *gradient = g.derivatives().size() == m ? VecX(g.derivatives()) : VecX::Zero(m);
  return g.value();
}

}  // namespace kontakt::assembly
