#include "render/frame_header.hpp"

#include <array>
#include <cstdio>

#include "controllers/controller_registry.hpp"
#include "render/bitmap_font.hpp"
#include "render/frame_scene.hpp"
#include "render/palette.hpp"

namespace swarmagg {

std::string frame_caption(const SwarmSnapshot& snapshot) {
  char text[128];
  std::snprintf(text, sizeof text, "T=%.10g  STEP=%lld  NOA=%d", snapshot.time,
                static_cast<long long>(snapshot.step), snapshot.noa);
  return text;
}

bool add_frame_header(FrameScene& scene, const FrameLayout& layout, const SwarmSnapshot& snapshot) {
  const int k = layout.text_scale;
  const int y = kTextPadding * k;
  const int left = kTextPadding * k;
  const std::string caption = frame_caption(snapshot);
  scene.labels.push_back({left, y, k, palette::kText, caption});
  const int caption_end = left + text_width(caption, k);

  std::array<AgentState, kAgentStateCount> states{AgentState::Go, AgentState::Approach,
                                                  AgentState::Wait, AgentState::Leave};
  const bool approach =
      snapshot.spec != nullptr && controller_rules(*snapshot.spec).allows(AgentState::Approach);
  const int swatch = kGlyphHeight * k;
  const int gap = 2 * k;
  const int spacing = 8 * k;
  int legend_width = 0;
  for (const AgentState s : states) {
    if (s == AgentState::Approach && !approach) continue;
    if (legend_width > 0) legend_width += spacing;
    legend_width += swatch + gap + text_width(to_string(s), k);
  }
  int x = layout.width - left - legend_width;
  if (x < caption_end + spacing) return false;
  for (const AgentState s : states) {
    if (s == AgentState::Approach && !approach) continue;
    scene.rects.push_back({x, y, swatch, swatch, palette::kBodyOutline});
    scene.rects.push_back({x + k, y + k, swatch - 2 * k, swatch - 2 * k, palette::state_colour(s)});
    const std::string name(to_string(s));
    scene.labels.push_back({x + swatch + gap, y, k, palette::kText, name});
    x += swatch + gap + text_width(name, k) + spacing;
  }
  return true;
}

bool draw_frame_header(std::span<std::uint8_t> rgba, const FrameLayout& layout,
                       const SwarmSnapshot& snapshot) {
  FrameScene header;
  const bool legend = add_frame_header(header, layout, snapshot);
  draw_scene_text(rgba, layout.width, layout.height, header);
  return legend;
}

}  // namespace swarmagg
