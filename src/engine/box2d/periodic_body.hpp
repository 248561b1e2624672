#pragma once
// One agent's Box2D body and its periodic images on a torus. An image is a second set of
// fixtures (sensors, and the solid disc when close enough to matter) on the same body,
// offset by a whole period (+-W, +-H), kept while the agent is near an edge. Contacts with an
// image therefore act on the agent itself, within the same solver iteration: across the seam
// a collision is the same two-body problem as in mid-arena (no ghost body of infinite or
// doubled mass). When the centre leaves the arena the body is moved one period back and the
// image offsets are relabelled so that no fixture moves in the world: contacts and sensor
// overlaps survive the jump.
#include <box2d/box2d.h>

#include <array>
#include <cstdint>

#include "control_interface/neighbour_lists.hpp"

namespace swarmagg::box2d {

// The fixture geometry every agent shares (Box2D works in float).
struct BodyShapes {
  float solid_radius = 1.0f;   // r
  float detect_radius = 2.0f;  // s / 2
  float sense_radius = 0.0f;   // R / 2 when the sensing radius R exceeds s, else 0 (none)
  float width = 180.0f;        // arena period
  float height = 180.0f;
  bool torus = true;
  // An image's sensors are added when the centre comes this close to an edge and removed
  // beyond the keep margin; its solid disc likewise, with the (smaller) solid margins.
  float sensor_add_margin = 0.0f;
  float sensor_keep_margin = 0.0f;
  float solid_add_margin = 0.0f;
  float solid_keep_margin = 0.0f;
  float linear_damping = 0.0f;
};

class PeriodicBody {
 public:
  // Creates the body at `position` (inside the arena), with the images it needs there.
  void create(b2World& world, AgentId agent, b2Vec2 position, const BodyShapes& shapes);

  b2Body* body() const { return body_; }

  // Torus: if the centre has left [0, W) x [0, H), moves the body one period back (its
  // velocity and the world position of every fixture kept), then adds the images an agent
  // this close to an edge needs and drops those it no longer does (with hysteresis).
  void follow_torus();
  // The contact filter depends on the agent's signal: re-run it on every solid fixture.
  void refilter_solids();

 private:
  struct Image {
    std::int8_t ix = 0;  // offset in periods: the fixtures sit at (ix W, iy H) from the centre
    std::int8_t iy = 0;
    b2Fixture* solid = nullptr;  // always present on the image at offset zero
    b2Fixture* detect = nullptr;
    b2Fixture* sense = nullptr;
  };

  void wrap();
  void update_images();
  void add_image(int ix, int iy);
  void remove_image(int index);
  bool has_image(int ix, int iy) const;
  b2Vec2 offset_of(const Image& image) const;
  void place(Image& image) const;
  void fix_mass();

  b2Body* body_ = nullptr;
  AgentId agent_ = 0;
  const BodyShapes* shapes_ = nullptr;
  std::array<Image, 4> images_{};
  int count_ = 0;
};

}  // namespace swarmagg::box2d
