#include "contact/aabb_tree.hpp"

#include <algorithm>

namespace kontakt::contact {

namespace {
constexpr int kLeafSize = 4;
}

AabbTree::AabbTree(const std::vector<Box>& boxes) : boxes_(boxes) {
  items_.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) items_[i] = static_cast<int>(i);
  if (!boxes.empty()) build(items_, 0, static_cast<int>(boxes.size()), boxes);
}

int AabbTree::build(std::vector<int>& items, int first, int count, const std::vector<Box>& boxes) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Box box, centres;
  for (int k = first; k < first + count; ++k) {
    box.add(boxes[items[k]].lo);
    box.add(boxes[items[k]].hi);
    centres.add(0.5 * (boxes[items[k]].lo + boxes[items[k]].hi));
  }
  nodes_[id].box = box;
  if (count <= kLeafSize) {
    nodes_[id].first = first;
    nodes_[id].count = count;
    return id;
  }
  // Median split along the axis where the box centres spread most.
  int axis = 0;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(items.begin() + first, items.begin() + first + half, items.begin() + first + count,
                   [&](int a, int b) {
                     return boxes[a].lo(axis) + boxes[a].hi(axis) < boxes[b].lo(axis) + boxes[b].hi(axis);
                   });
  const int left = build(items, first, half, boxes);
  const int right = build(items, first + half, count - half, boxes);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

std::vector<int> AabbTree::overlapping(const Box& query) const {
  std::vector<int> found;
  if (nodes_.empty()) return found;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!node.box.overlaps(query)) continue;
    if (node.left < 0) {
      for (int k = node.first; k < node.first + node.count; ++k)
        if (boxes_[items_[k]].overlaps(query)) found.push_back(items_[k]);
      continue;
    }
    stack.push_back(node.left);
    stack.push_back(node.right);
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace kontakt::contact
