// Bounding-volume hierarchy over axis-aligned boxes: the broad phase of the contact search.
// Built once per increment over the master faces; queried with each slave face's box, so far
// apart faces never reach the narrow phase (clipping, projection).
#pragma once

#include <vector>

#include "core/types.hpp"

namespace kontakt::contact {

struct Box {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Box inflated(Real margin) const { return {lo.array() - margin, hi.array() + margin}; }
  bool overlaps(const Box& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

class AabbTree {
 public:
  AabbTree() = default;
  explicit AabbTree(const std::vector<Box>& boxes);

  /// Indices (into the boxes given at construction) of every box overlapping `query`,
  /// in ascending order.
  std::vector<int> overlapping(const Box& query) const;

 private:
  struct Node {
    Box box;
    int left = -1, right = -1;  ///< children; both -1 for a leaf
    int first = 0, count = 0;   ///< leaf: items_[first, first + count)
  };
  int build(std::vector<int>& items, int first, int count, const std::vector<Box>& boxes);

  std::vector<Node> nodes_;
  std::vector<int> items_;
  std::vector<Box> boxes_;
};

}  // namespace kontakt::contact
