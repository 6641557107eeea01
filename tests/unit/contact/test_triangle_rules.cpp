#include <gtest/gtest.h>

#include <cmath>

#include "contact/triangle_rules.hpp"
#include "core/error.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {
Real factorial(int n) { return n <= 1 ? 1 : n * factorial(n - 1); }
}  // namespace

TEST(TriangleRules, IntegrateMonomialsUpToTheirDegreeExactlyAndNoFurther) {
  for (int n : {1, 3, 7, 12}) {
    const auto rule = triangle_rule(n);
    ASSERT_EQ(static_cast<int>(rule.size()), n);
    const int degree = triangle_rule_degree(n);
    Real weights = 0;
    for (const auto& p : rule) {
      EXPECT_NEAR(p.l1 + p.l2 + p.l3, 1.0, 1e-15);
      EXPECT_GT(p.l1, 0);
      weights += p.weight;
    }
    EXPECT_NEAR(weights, 1.0, 1e-14);
    bool exact_beyond = true;
    for (int i = 0; i <= degree + 1; ++i)
      for (int j = 0; i + j <= degree + 1; ++j) {
        // Reference triangle (0,0), (1,0), (0,1), area 1/2: integral of x^i y^j.
        const Real exact = factorial(i) * factorial(j) / factorial(i + j + 2);
        Real sum = 0;
        for (const auto& p : rule) sum += 0.5 * p.weight * std::pow(p.l2, i) * std::pow(p.l3, j);
        if (i + j <= degree)
          EXPECT_NEAR(sum, exact, 1e-14) << n << " points, x^" << i << " y^" << j;
        else
          exact_beyond &= std::abs(sum - exact) < 1e-14;
      }
    EXPECT_FALSE(exact_beyond) << n << " points integrate beyond their advertised degree";
  }
  EXPECT_THROW(triangle_rule(4), SolverError);
}
