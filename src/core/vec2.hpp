#pragma once
// A 2D vector of doubles: positions, offsets and velocities in arena units.
#include <bit>
#include <cmath>
#include <cstdint>

namespace swarmagg {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double k) {
    x *= k;
    y *= k;
    return *this;
  }
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double k) { return {a.x * k, a.y * k}; }
  friend constexpr Vec2 operator*(double k, Vec2 a) { return {a.x * k, a.y * k}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
constexpr double norm2(Vec2 a) {
  return dot(a, a);
}
inline double norm(Vec2 a) {
  return std::sqrt(norm2(a));
}
// v == 0, as one test (&& would make two branches, each hard to predict).
constexpr bool is_zero(Vec2 v) {
  return (v.x == 0.0) & (v.y == 0.0);
}
// Bit for bit, so that -0.0 and +0.0 differ: what an agent that did not move keeps.
constexpr bool same_bits(Vec2 a, Vec2 b) {
  return (std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x)) &
         (std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y));
}
inline Vec2 from_angle(double radians) {
  return {std::cos(radians), std::sin(radians)};
}

}  // namespace swarmagg
