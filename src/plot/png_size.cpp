#include "plot/png_size.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace swarmagg {
namespace {

constexpr std::array<unsigned char, 8> kSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

int big_endian(const unsigned char* bytes) {
  return static_cast<int>((std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                          (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]});
}

}  // namespace

std::optional<PngSize> png_size(const std::filesystem::path& file) {
  // Signature (8), IHDR length (4), "IHDR" (4), width (4), height (4).
  std::array<unsigned char, 24> header{};
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(header.data()), header.size())) return std::nullopt;
  if (!std::equal(kSignature.begin(), kSignature.end(), header.begin()) ||
      std::memcmp(header.data() + 12, "IHDR", 4) != 0) {
    return std::nullopt;
  }
  return PngSize{big_endian(header.data() + 16), big_endian(header.data() + 20)};
}

bool png_complete(const std::filesystem::path& file) {
  // The IEND chunk: length 0, its type, and the CRC of the type.
  constexpr std::array<unsigned char, 12> kEnd{0,   0,   0,    0,    'I',  'E',
                                               'N', 'D', 0xae, 0x42, 0x60, 0x82};
  if (!png_size(file)) return false;
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() < static_cast<std::streamoff>(kSignature.size() + kEnd.size()))
    return false;
  std::array<unsigned char, 12> end{};
  in.seekg(-static_cast<std::streamoff>(end.size()), std::ios::end);
  if (!in.read(reinterpret_cast<char*>(end.data()), end.size())) return false;
  return end == kEnd;
}

}  // namespace swarmagg
