#pragma once
// Bumper bits an engine sets when a wall reflected an agent during the last step, so the
// controller can turn its heading the same way (one byte per agent).
#include <cstdint>

namespace swarmagg {

enum Reflection : std::uint8_t { ReflectedX = 1, ReflectedY = 2 };

}  // namespace swarmagg
