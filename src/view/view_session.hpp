#pragma once
// What the live view shows and does, without a window: one replicate of a world, stepped
// on this thread when the run control says so, the scene options, the selection, and what
// the panel reads (state counts, NOA history, the model's NOA curve, an agent's details).
// Commands from keys and from a --script file arrive here through apply(). The view only
// reads the replicate: it draws no random numbers and changes nothing of its state, so a
// viewed replicate goes through exactly the steps a batch run takes.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "render/scene_options.hpp"
#include "run/replicate.hpp"
#include "view/run_control.hpp"
#include "view/view_command.hpp"

namespace swarmagg {

struct StateTransition {
  AgentState from = AgentState::Go;
  AgentState to = AgentState::Go;
  std::int64_t step = 0;
};

// What the inspector shows of one agent.
struct AgentDetails {
  std::int32_t id = -1;
  Vec2 position;
  Vec2 heading;
  AgentState state = AgentState::Go;
  double time_in_state = 0.0;             // tu since the agent entered its state (or since step 0)
  std::vector<std::uint32_t> neighbours;  // within the detection radius, nearest first
  std::int32_t aggregate = -1;
  std::int32_t aggregate_size = 0;
  std::optional<StateTransition> last_transition;
  // In APPROACH: the nearest perceived agent within the approach radius that is not
  // leaving, which is the one the Soysal rule steers towards.
  std::optional<std::uint32_t> approaching;
};

struct NoaPoint {
  double time = 0.0;
  double noa = 0.0;
};

class ViewSession {
 public:
  // `out` receives the hash lines and the end-of-run summary line.
  ViewSession(WorldSpec spec, int replicate, std::ostream& out);
  ~ViewSession();

  // Carries out a command; the window handles Screenshot and Record (see take_*).
  void apply(const ViewCommand& command);
  // Steps n times now, keeping the panel's records up to date.
  void step(std::int64_t n);
  // One frame's worth of steps by the run control; stops early when `budget_seconds` of wall
  // time are spent (Fastest pace). Returns the steps taken.
  std::int64_t advance_frame(double frame_seconds, double budget_seconds);

  const WorldSpec& spec() const { return *spec_; }
  const Replicate& replicate() const { return *replicate_; }
  SwarmSnapshot snapshot() const { return replicate_->snapshot(); }
  RunControl& control() { return control_; }
  const RunControl& control() const { return control_; }
  SceneOptions& scene() { return scene_; }
  const SceneOptions& scene() const { return scene_; }
  SceneExtras extras() const;
  bool panel() const { return panel_; }
  void set_panel(bool on) { panel_ = on; }
  bool quit_requested() const { return quit_; }
  bool follow = false;               // keep the selected agent in the view's centre
  std::function<void()> after_step;  // called after every step (the window records frames)

  std::optional<AgentDetails> details(std::int32_t agent) const;
  std::vector<std::int32_t> state_counts() const;  // by AgentState
  const std::vector<NoaPoint>& noa_history() const { return noa_history_; }
  const std::vector<NoaPoint>& model_noa() const { return model_noa_; }
  std::string hash_line() const;  // "state-hash <hex> step <n>"

  // A screenshot or a start or stop of recording asked for by a command, once.
  std::optional<std::string> take_screenshot_request();
  std::optional<bool> take_record_request();  // start (true) or stop (false) recording

 private:
  void restart();
  void observe_step();
  void set_overlay(Overlay overlay, bool on);

  std::unique_ptr<WorldSpec> spec_;
  int index_;
  std::ostream& out_;
  std::unique_ptr<Replicate> replicate_;
  RunControl control_;
  SceneOptions scene_;
  bool panel_ = true;
  bool quit_ = false;
  std::optional<std::string> screenshot_;
  std::optional<bool> record_;
  double wall_seconds_ = 0.0;  // stepping time since the last restart

  std::vector<AgentState> previous_state_;
  std::vector<std::int64_t> state_since_;
  std::vector<std::optional<StateTransition>> last_transition_;
  std::vector<NoaPoint> noa_history_;
  std::vector<NoaPoint> model_noa_;
  std::vector<Vec2> trail_;  // trail_frames_ blocks of positions, oldest first
  int trail_frames_ = 0;
};

inline constexpr int kTrailFrames = 40;

}  // namespace swarmagg
