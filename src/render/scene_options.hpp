#pragma once
// What a scene shows beyond the swarm itself: how bodies are coloured, which overlays are
// on, the agent selected, and the zoom and centre of the view. The defaults are the frame
// `run --render-every` draws: bodies by state, aggregate tints, every detection circle,
// aggregate links and torus seam copies, the whole arena in view. The live view changes
// these; the swarm's state is only read.
#include <cstdint>
#include <optional>
#include <span>

#include "core/vec2.hpp"

namespace swarmagg {

enum class ColourMode { State, Aggregate, Size };

// Which agents a radius overlay is drawn for.
enum class OverlayScope { None, Selected, All };

struct SceneOptions {
  ColourMode colour = ColourMode::State;
  bool tints = true;                           // aggregate tint under members
  OverlayScope detection = OverlayScope::All;  // circle of radius s
  OverlayScope approach = OverlayScope::None;  // circle of radius s_a (Soysal)
  bool links = true;                           // members of one aggregate within s
  bool neighbour_links = false;                // every pair within s, aggregated or not
  bool ghosts = true;                          // copies across the torus seam
  bool contacts = false;                       // bodies touching (centres within 2r)
  bool trails = false;                         // drawn from SceneExtras::trail
  std::int32_t selected = -1;                  // agent index, -1 for none
  double zoom = 1.0;                           // 1: the arena fits the frame
  std::optional<Vec2> centre;                  // arena point at the view's centre; none: fit

  bool fits() const { return zoom == 1.0 && !centre; }
};

// Data the scene draws that a snapshot does not hold.
struct SceneExtras {
  // Past positions, oldest first: trail_frames blocks of one position per agent.
  std::span<const Vec2> trail;
  int trail_frames = 0;
};

}  // namespace swarmagg
