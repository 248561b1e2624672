#include "engine/box2d/sensor_links.hpp"

#include <algorithm>
#include <stdexcept>

namespace swarmagg::box2d {
namespace {

std::uint16_t& count_of(SensorLink& link, SensorKind kind) {
  return kind == SensorKind::Detect ? link.detect : link.sense;
}

std::vector<SensorLink>::iterator find_link(std::vector<SensorLink>& links, AgentId other) {
  return std::find_if(links.begin(), links.end(),
                      [other](const SensorLink& l) { return l.other == other; });
}

// Links an agent usually has at once: reserved up front, so that the first few neighbours
// of every agent do not each grow its vector during the run (it still grows beyond this).
constexpr std::size_t kTypicalLinks = 8;

}  // namespace

void SensorLinks::reset(std::size_t agent_count) {
  links_.resize(agent_count);
  for (auto& links : links_) {
    links.clear();
    links.reserve(kTypicalLinks);
  }
}

SensorLink& SensorLinks::find_or_add(AgentId a, AgentId b) {
  auto& links = links_[a];
  const auto it = find_link(links, b);
  if (it != links.end()) return *it;
  links.push_back({b, 0, 0});
  return links.back();
}

bool SensorLinks::begin(AgentId a, AgentId b, SensorKind kind) {
  ++count_of(find_or_add(b, a), kind);
  return ++count_of(find_or_add(a, b), kind) == 1;
}

void SensorLinks::end(AgentId a, AgentId b, SensorKind kind) {
  const auto forget = [&](AgentId from, AgentId to) {
    auto& links = links_[from];
    const auto it = find_link(links, to);
    if (it == links.end() || count_of(*it, kind) == 0) {
      throw std::logic_error("Box2D engine: sensor end event without a matching begin");
    }
    --count_of(*it, kind);
    if (it->detect == 0 && it->sense == 0) {
      *it = links.back();
      links.pop_back();
    }
  };
  forget(a, b);
  forget(b, a);
}

}  // namespace swarmagg::box2d
