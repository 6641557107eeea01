// The Newton driver with penalty contact on two stacked blocks: the contact patch test
// (thesis section 5.4) per scheme, and the driver's contact bookkeeping.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/nonlinear_static.hpp"
#include "../contact/two_blocks.hpp"

using namespace kontakt;

namespace {

struct Collect : analysis::FrameSink, analysis::EventSink {
  std::vector<output::Frame> frames;
  std::vector<analysis::Event> events;
  void on_frame(const model::Step&, const output::Frame& f) override { frames.push_back(f); }
  void on_event(const analysis::Event& e) override { events.push_back(e); }
};

struct PatchResult {
  Real szz_min = 1e300, szz_max = -1e300, cpress_min = 1e300, cpress_max = -1e300;
  int iterations = 0;
};

/// Upper block coarse (2 x 2 C3D15 wedges: 6-node triangle faces), lower fine (3 x 3 C3D20),
/// nu = 0, unit pressure, K = 1e7: the exact state is sigma_zz = -1 and p = 1 everywhere.
PatchResult patch_test(const std::string& scheme) {
  contact::fixtures::TwoBlocks t;
  t.upper = {"C3D15", 2, 1};
  t.lower = {"C3D20", 3, 2};
  const model::Model m =
      contact::fixtures::two_blocks_model(t, 1e7, *model::contact_scheme_from_name(scheme));
  Collect c;
  analysis::run_nonlinear_static(m, {}, c, c);
  PatchResult r;
  const output::Frame& f = c.frames.back();
  for (Index k = 0; k < f.S.rows(); ++k) {
    r.szz_min = std::min(r.szz_min, f.S(k, 2));
    r.szz_max = std::max(r.szz_max, f.S(k, 2));
  }
  for (const auto& p : f.contact_points) {
    if (!p.active) continue;
    r.cpress_min = std::min(r.cpress_min, p.pressure);
    r.cpress_max = std::max(r.cpress_max, p.pressure);
  }
  r.iterations = c.events.back().iterations;
  return r;
}

}  // namespace

TEST(ContactPatchTest, GaussCutSchemesTransmitTheUniformState) {
  // The 3-point rule integrates the face-pair products (degree 4) inexactly, so the point
  // pressures scatter a little more; the stresses are uniform to 1e-3 for all.
  for (const auto& [scheme, p_tol] : {std::pair{"lgc3", 5e-3}, {"lgc7", 1e-3}, {"lgc12", 1e-3}, {"gc7", 1e-3}}) {
    const PatchResult r = patch_test(scheme);
    std::printf("%-6s szz %.6f .. %.6f  point pressure %.6f .. %.6f  iterations %d\n", scheme,
                r.szz_min, r.szz_max, r.cpress_min, r.cpress_max, r.iterations);
    SCOPED_TRACE(scheme);
    EXPECT_NEAR(r.szz_min, -1, 1e-3);
    EXPECT_NEAR(r.szz_max, -1, 1e-3);
    EXPECT_NEAR(r.cpress_min, 1, p_tol);
    EXPECT_NEAR(r.cpress_max, 1, p_tol);
  }
}

TEST(ContactPatchTest, NodeToSurfaceAndGaussFailItAsInTheThesis) {
  for (const char* scheme : {"nts", "lgauss", "gauss"}) {
    const PatchResult r = patch_test(scheme);
    std::printf("%-6s szz %.6f .. %.6f  point pressure %.6f .. %.6f  iterations %d\n", scheme,
                r.szz_min, r.szz_max, r.cpress_min, r.cpress_max, r.iterations);
    SCOPED_TRACE(scheme);
    EXPECT_GT(std::max(std::abs(r.szz_min + 1), std::abs(r.szz_max + 1)), 1e-2);
  }
}
