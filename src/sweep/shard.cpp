#include "sweep/shard.hpp"

#include <charconv>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

bool read_int(const std::string& text, int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard shard;
  const bool parsed = slash != std::string::npos && read_int(text.substr(0, slash), shard.index) &&
                      read_int(text.substr(slash + 1), shard.count);
  if (!parsed || shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw InputError("--shard " + text + ": expected i/n with 1 <= i <= n, e.g. --shard 2/8");
  }
  return shard;
}

}  // namespace swarmagg
