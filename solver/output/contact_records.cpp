#include "output/contact_records.hpp"

namespace kontakt::output {

ContactPointRecord merged_record(std::span<const ContactPointRecord> records) {
  ContactPointRecord r = records.front();
  r.area = r.energy = r.clearance = r.pressure = 0;
  r.slip = r.shear = Vec2::Zero();
  r.active = false;
  bool slipping = false, sticking = false;
  for (const auto& s : records) {
    r.area += s.area;
    r.energy += s.energy;
    r.clearance += s.area * s.clearance;
    r.pressure += s.area * s.pressure;
    r.slip += s.area * s.slip;
    r.shear += s.area * s.shear;
    r.active |= s.active;
    slipping |= s.active && !s.sticking;
    sticking |= s.sticking;
  }
  const Real w = r.area > 0 ? 1 / r.area : 0;
  r.clearance *= w;
  r.pressure *= w;
  r.slip *= w;
  r.shear *= w;
  r.sticking = sticking && !slipping;
  return r;
}

}  // namespace kontakt::output
