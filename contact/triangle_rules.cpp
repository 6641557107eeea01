#include "contact/triangle_rules.hpp"

#include <array>

#include "core/error.hpp"

namespace kontakt::contact {

namespace {

constexpr TrianglePoint kOne[] = {{1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0}};

// Degree 2: the three interior points (2/3, 1/6, 1/6).
constexpr TrianglePoint kThree[] = {{2.0 / 3, 1.0 / 6, 1.0 / 6, 1.0 / 3},
                                    {1.0 / 6, 2.0 / 3, 1.0 / 6, 1.0 / 3},
                                    {1.0 / 6, 1.0 / 6, 2.0 / 3, 1.0 / 3}};

// Degree 5 (Radon's 7-point rule): a = (6 - sqrt 15)/21, b = (6 + sqrt 15)/21.
constexpr Real a7 = 0.101286507323456338800987361915123;
constexpr Real b7 = 0.470142064105115089770441209513447;
constexpr Real w7a = 0.125939180544827152595683945500181;
constexpr Real w7b = 0.132394152788506180737649387833152;
constexpr TrianglePoint kSeven[] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225},
    {1 - 2 * a7, a7, a7, w7a}, {a7, 1 - 2 * a7, a7, w7a}, {a7, a7, 1 - 2 * a7, w7a},
    {1 - 2 * b7, b7, b7, w7b}, {b7, 1 - 2 * b7, b7, w7b}, {b7, b7, 1 - 2 * b7, w7b}};

// Degree 6 (Dunavant's 12-point rule).
constexpr Real a12 = 0.063089014491502228340331602870819;
constexpr Real b12 = 0.249286745170910421291638553107019;
constexpr Real c12 = 0.053145049844816947353249671631398;
constexpr Real d12 = 0.310352451033784405416607733956552;
constexpr Real wa12 = 0.050844906370206816920936809106869;
constexpr Real wb12 = 0.116786275726379366030690538023981;
constexpr Real wc12 = 0.082851075618373575193553456420443;
constexpr Real e12 = 1 - c12 - d12;
constexpr TrianglePoint kTwelve[] = {
    {1 - 2 * a12, a12, a12, wa12}, {a12, 1 - 2 * a12, a12, wa12}, {a12, a12, 1 - 2 * a12, wa12},
    {1 - 2 * b12, b12, b12, wb12}, {b12, 1 - 2 * b12, b12, wb12}, {b12, b12, 1 - 2 * b12, wb12},
    {c12, d12, e12, wc12}, {d12, c12, e12, wc12}, {c12, e12, d12, wc12},
    {e12, c12, d12, wc12}, {d12, e12, c12, wc12}, {e12, d12, c12, wc12}};

}  // namespace

std::span<const TrianglePoint> triangle_rule(int n_points) {
  switch (n_points) {
    case 1: return kOne;
    case 3: return kThree;
    case 7: return kSeven;
    case 12: return kTwelve;
  }
  throw SolverError("no triangle rule with " + std::to_string(n_points) +
                    " points (1, 3, 7 or 12)");
}

int triangle_rule_degree(int n_points) {
  switch (n_points) {
    case 1: return 1;
    case 3: return 2;
    case 7: return 5;
    case 12: return 6;
  }
  throw SolverError("no triangle rule with " + std::to_string(n_points) + " points");
}

}  // namespace kontakt::contact
