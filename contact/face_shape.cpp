#include "contact/face_shape.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace kontakt::contact {

using element::Topology;

namespace {

void tri(const Vec2& xi, bool quadratic, FaceShape& s) {
  const Real L[3] = {1 - xi(0) - xi(1), xi(0), xi(1)};
  const Vec2 dL[3] = {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
  auto hess_row = [](const Vec2& a, const Vec2& b) {  // symmetrised a (x) b + b (x) a
    return Eigen::Matrix<Real, 1, 3>(2 * a(0) * b(0), 2 * a(1) * b(1), a(0) * b(1) + a(1) * b(0));
  };
  const int n = quadratic ? 6 : 3;
  s.N.resize(n);
  s.dN.resize(n, 2);
  s.d2N.setZero(n, 3);
  if (!quadratic) {
    for (int i = 0; i < 3; ++i) {
      s.N(i) = L[i];
      s.dN.row(i) = dL[i].transpose();
    }
    return;
  }
  for (int i = 0; i < 3; ++i) {
    s.N(i) = L[i] * (2 * L[i] - 1);
    s.dN.row(i) = (4 * L[i] - 1) * dL[i].transpose();
    s.d2N.row(i) = 2 * hess_row(dL[i], dL[i]);
  }
  static constexpr int kEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int k = 0; k < 3; ++k) {
    const int a = kEdge[k][0], b = kEdge[k][1];
    s.N(3 + k) = 4 * L[a] * L[b];
    s.dN.row(3 + k) = 4 * (L[b] * dL[a] + L[a] * dL[b]).transpose();
    s.d2N.row(3 + k) = 4 * hess_row(dL[a], dL[b]);
  }
}

void quad(const Vec2& xi, bool quadratic, FaceShape& s) {
  static constexpr Real kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const Real x = xi(0), y = xi(1);
  const int n = quadratic ? 8 : 4;
  s.N.resize(n);
  s.dN.resize(n, 2);
  s.d2N.setZero(n, 3);
  for (int i = 0; i < 4; ++i) {
    const Real a = kCorner[i][0], b = kCorner[i][1];
    const Real A = 1 + a * x, B = 1 + b * y;
    if (!quadratic) {
      s.N(i) = 0.25 * A * B;
      s.dN.row(i) << 0.25 * a * B, 0.25 * b * A;
      s.d2N(i, 2) = 0.25 * a * b;
      continue;
    }
    s.N(i) = 0.25 * A * B * (a * x + b * y - 1);
    s.dN.row(i) << 0.25 * a * B * (2 * a * x + b * y), 0.25 * b * A * (2 * b * y + a * x);
    s.d2N.row(i) << 0.5 * B, 0.5 * A, 0.25 * a * b * (2 * a * x + 2 * b * y + 1);
  }
  if (!quadratic) return;
  // Midside nodes 5 (eta = -1), 7 (eta = +1) on xi-edges; 6 (xi = +1), 8 (xi = -1).
  for (int k : {4, 6}) {
    const Real b = k == 4 ? -1 : 1, B = 1 + b * y;
    s.N(k) = 0.5 * (1 - x * x) * B;
    s.dN.row(k) << -x * B, 0.5 * (1 - x * x) * b;
    s.d2N.row(k) << -B, 0, -x * b;
  }
  for (int k : {5, 7}) {
    const Real a = k == 5 ? 1 : -1, A = 1 + a * x;
    s.N(k) = 0.5 * A * (1 - y * y);
    s.dN.row(k) << 0.5 * a * (1 - y * y), -y * A;
    s.d2N.row(k) << 0, -A, -y * a;
  }
}

}  // namespace

bool is_face_topology(Topology topo) {
  return topo == Topology::Tri3 || topo == Topology::Tri6 || topo == Topology::Quad4 ||
         topo == Topology::Quad8;
}

bool is_triangle(Topology topo) { return topo == Topology::Tri3 || topo == Topology::Tri6; }

void face_shape(Topology topo, const Vec2& xi, FaceShape& out) {
  switch (topo) {
    case Topology::Tri3: return tri(xi, false, out);
    case Topology::Tri6: return tri(xi, true, out);
    case Topology::Quad4: return quad(xi, false, out);
    case Topology::Quad8: return quad(xi, true, out);
    default: throw SolverError("face_shape: not a face topology");
  }
}

Vec2 face_centre(Topology topo) {
  return is_triangle(topo) ? Vec2(1.0 / 3, 1.0 / 3) : Vec2(0, 0);
}

bool inside_reference_face(Topology topo, const Vec2& xi, Real tol) {
  if (is_triangle(topo)) return xi(0) >= -tol && xi(1) >= -tol && xi(0) + xi(1) <= 1 + tol;
  return std::abs(xi(0)) <= 1 + tol && std::abs(xi(1)) <= 1 + tol;
}

Vec2 clamp_to_reference_face(Topology topo, const Vec2& xi) {
  if (!is_triangle(topo)) return xi.cwiseMax(-1).cwiseMin(1);
  if (inside_reference_face(topo, xi, 0)) return xi;
  // Nearest point on each edge of the reference triangle; keep the closest.
  const Vec2 v[3] = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  Vec2 best = v[0];
  Real best_d = (xi - best).squaredNorm();
  for (int e = 0; e < 3; ++e) {
    const Vec2 a = v[e], b = v[(e + 1) % 3], ab = b - a;
    const Real t = std::clamp((xi - a).dot(ab) / ab.squaredNorm(), Real(0), Real(1));
    const Vec2 q = a + t * ab;
    if ((xi - q).squaredNorm() < best_d) {
      best_d = (xi - q).squaredNorm();
      best = q;
    }
  }
  return best;
}

}  // namespace kontakt::contact
