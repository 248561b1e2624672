#pragma once
// Disjoint sets over agent indices, with path halving. A union links the higher of the two
// roots under the lower, so every set's root is its lowest element and parent(a) <= a:
// walking the elements in increasing order, each reaches its root in one step (settle()).
// Each set is also a cycle through next(), so its elements can be listed from any one.
#include <algorithm>
#include <cstdint>

#include "core/agent_array.hpp"

namespace swarmagg {

class UnionFind {
 public:
  // Room for n elements without initialising them: only make_set()'s elements may be used.
  void reserve_elements(std::size_t n) {
    parent_.resize(n);
    size_.resize(n);
    next_.resize(n);
  }
  void make_set(std::uint32_t a) {
    parent_[a] = a;
    size_[a] = 1;
    next_[a] = a;
  }
  // A loop, not a fixed number of steps without a branch: that saves mispredictions in
  // small swarms, but in large ones the predicted exit is what lets the next loads start
  // before this element's cache miss returns (AggregateTracker::update took 1.4 times as
  // long on a million agents).
  std::uint32_t find(std::uint32_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];
      a = parent_[a];
    }
    return a;
  }
  // Without a branch on whether a and b already share a set: then nothing changes (the
  // root stays its own parent, its size gains nothing, swapping a cycle's links with
  // themselves leaves them).
  void unite(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t root_a = find(a);
    const std::uint32_t root_b = find(b);
    const std::uint32_t low = std::min(root_a, root_b);
    const std::uint32_t high = std::max(root_a, root_b);
    // By a mask: a compiler turns the choice back into a branch, which mispredicts whenever
    // a link closes a loop (two members of one aggregate both within s of a third).
    size_[low] += size_[high] & (0u - static_cast<std::uint32_t>(low != high));
    parent_[high] = low;
    std::swap(next_[root_a], next_[root_b]);  // splices the two cycles into one
  }
  // a's root, in one step, provided every lower element of a's set went through settle()
  // since the last unite(): its parent is then the root or an element pointing at it.
  std::uint32_t settle(std::uint32_t a) {
    const std::uint32_t root = parent_[parent_[a]];
    parent_[a] = root;
    return root;
  }
  std::uint32_t size_of_root(std::uint32_t root) const { return size_[root]; }
  // The element after a in its set's cycle.
  std::uint32_t next(std::uint32_t a) const { return next_[a]; }

 private:
  AgentArray<std::uint32_t> parent_;
  AgentArray<std::uint32_t> size_;
  AgentArray<std::uint32_t> next_;
};

}  // namespace swarmagg
