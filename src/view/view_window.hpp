#pragma once
// The live view's window (GLFW 3.3 + Dear ImGui 1.86): each frame, on one thread, it takes the
// queued commands (keys, mouse, panel, one --script line), lets the session step, draws the
// scene off-screen with the same FrameRenderer that writes PNG frames, shows it 1:1 in the
// window with the panel on top, and then writes any screenshot from the window's pixels. So
// a screenshot with the panel off is the frame `run --render-every` draws, pixel for pixel.
//
// The scene's GL context is OSMesa's and the window's is GLX; the two share Mesa's dispatch
// (libglapi), so only one is current at a time: the window's context is released while the
// scene is drawn. Window-side GL calls go through pointers from glfwGetProcAddress (ImGui's
// backend loads its own), never through the process's gl* symbols, which are OSMesa's.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "view/view_command.hpp"
#include "view/view_session.hpp"

namespace swarmagg {

struct ViewWindowOptions {
  int width = 800;
  int height = 800;
  std::vector<ViewCommand> script;  // one command per frame, in order
  // After this many frames (0: never), quit and print the frame rate and where a frame's
  // time went (bench/view_fps.sh).
  std::int64_t frames = 0;
};

// Throws InputError (exit 2) when no display can be opened, saying how to run under Xvfb.
// Returns when the window is closed or `quit` runs.
void run_view_window(ViewSession& session, const ViewWindowOptions& options);

// Why a window cannot open here (no DISPLAY), or empty.
std::string display_problem();

}  // namespace swarmagg
