#pragma once
// Milliseconds to draw one frame (no PNG encoding): `agents` agents at the paper's density,
// a third of them waiting in pairs, at width x height; first frame (shader compilation)
// excluded, mean over `frames` frames.
namespace swarmagg {

double render_ms_per_frame(int agents, int width, int height, int frames);

}  // namespace swarmagg
