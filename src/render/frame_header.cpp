#include "render/frame_header.hpp"

#include <array>
#include <cstdio>

#include "controllers/controller_registry.hpp"
#include "render/bitmap_font.hpp"
#include "render/palette.hpp"

namespace swarmagg {

std::string frame_caption(const SwarmSnapshot& snapshot) {
  char text[128];
  std::snprintf(text, sizeof text, "T=%.10g  STEP=%lld  NOA=%d", snapshot.time,
                static_cast<long long>(snapshot.step), snapshot.noa);
  return text;
}

bool draw_frame_header(std::span<std::uint8_t> rgba, const FrameLayout& layout,
                       const SwarmSnapshot& snapshot) {
  const int k = layout.text_scale;
  const int y = kTextPadding * k;
  const int left = kTextPadding * k;
  const int caption_end = draw_text(rgba, layout.width, layout.height, left, y, k, palette::kText,
                                    frame_caption(snapshot));

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
    fill_rect(rgba, layout.width, layout.height, x, y, swatch, swatch, palette::kBodyOutline);
    fill_rect(rgba, layout.width, layout.height, x + k, y + k, swatch - 2 * k, swatch - 2 * k,
              palette::state_colour(s));
    x = draw_text(rgba, layout.width, layout.height, x + swatch + gap, y, k, palette::kText,
                  to_string(s)) +
        spacing;
  }
  return true;
}

}  // namespace swarmagg
