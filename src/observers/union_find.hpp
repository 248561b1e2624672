#pragma once
// Disjoint sets over agent indices, with path halving and union by size.
#include <cstdint>
#include <numeric>
#include <vector>

#include "core/agent_array.hpp"

namespace swarmagg {

class UnionFind {
 public:
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0u);
    size_.assign(n, 1u);
  }
  // Room for n elements without initialising them: only make_set()'s elements may be used.
  void reserve_elements(std::size_t n) {
    parent_.resize(n);
    size_.resize(n);
  }
  void make_set(std::uint32_t a) {
    parent_[a] = a;
    size_[a] = 1;
  }
  std::uint32_t find(std::uint32_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];
      a = parent_[a];
    }
    return a;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  std::uint32_t size_of(std::uint32_t a) { return size_[find(a)]; }

 private:
  AgentArray<std::uint32_t> parent_;
  AgentArray<std::uint32_t> size_;
};

}  // namespace swarmagg
