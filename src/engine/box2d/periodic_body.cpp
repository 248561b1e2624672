#include "engine/box2d/periodic_body.hpp"

#include <cmath>

#include "engine/box2d/fixture_tags.hpp"

namespace swarmagg::box2d {
namespace {

// +1 when the coordinate is within `margin` of the low edge (its image sits one period up),
// -1 near the high edge, 0 in between.
int near_side(float c, float length, float margin) {
  if (c < margin) return 1;
  if (c > length - margin) return -1;
  return 0;
}

// Whether an image at offset (ix, iy) belongs to a body on sides (sx, sy) of the arena.
bool image_fits(int ix, int iy, int sx, int sy) {
  return (ix == 0 || ix == sx) && (iy == 0 || iy == sy);
}

b2Fixture* make_fixture(b2Body* body, AgentId agent, FixtureRole role, float radius,
                        b2Vec2 offset) {
  b2CircleShape circle;
  circle.m_radius = radius;
  circle.m_p = offset;
  b2FixtureDef def;
  def.shape = &circle;
  // Density 0 everywhere: the mass is set explicitly (fix_mass) so that images, wherever
  // they are, never move the centre of mass away from the agent's centre.
  def.density = 0.0f;
  def.friction = 0.0f;  // robots slide along each other
  def.restitution = 0.0f;
  def.isSensor = role != FixtureRole::Solid;
  def.filter = filter_for(role);
  def.userData.pointer = encode_tag({agent, role});
  return body->CreateFixture(&def);
}

}  // namespace

void PeriodicBody::create(b2World& world, AgentId agent, b2Vec2 position,
                          const BodyShapes& shapes) {
  shapes_ = &shapes;
  agent_ = agent;
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = position;
  def.fixedRotation = true;  // discs: a contact far from the centre (an image) exerts no torque
  def.allowSleep = false;
  def.linearDamping = shapes.linear_damping;
  def.userData.pointer = agent;
  body_ = world.CreateBody(&def);
  count_ = 0;
  add_image(0, 0);
  fix_mass();
  if (shapes.torus) update_images();
}

void PeriodicBody::fix_mass() {
  b2MassData mass;
  mass.mass = 1.0f;
  mass.center.SetZero();
  mass.I = 0.0f;
  body_->SetMassData(&mass);
}

b2Vec2 PeriodicBody::offset_of(const Image& image) const {
  return {static_cast<float>(image.ix) * shapes_->width,
          static_cast<float>(image.iy) * shapes_->height};
}

void PeriodicBody::place(Image& image) const {
  const b2Vec2 offset = offset_of(image);
  for (b2Fixture* f : {image.solid, image.detect, image.sense}) {
    if (f != nullptr) static_cast<b2CircleShape*>(f->GetShape())->m_p = offset;
  }
}

bool PeriodicBody::has_image(int ix, int iy) const {
  for (int k = 0; k < count_; ++k) {
    if (images_[k].ix == ix && images_[k].iy == iy) return true;
  }
  return false;
}

void PeriodicBody::add_image(int ix, int iy) {
  Image& image = images_[count_++];
  image.ix = static_cast<std::int8_t>(ix);
  image.iy = static_cast<std::int8_t>(iy);
  const b2Vec2 offset = offset_of(image);
  // The solid disc of an image is added by update_images, in its narrower band.
  image.solid = ix == 0 && iy == 0
                    ? make_fixture(body_, agent_, FixtureRole::Solid, shapes_->solid_radius, offset)
                    : nullptr;
  image.detect = make_fixture(body_, agent_, FixtureRole::Detect, shapes_->detect_radius, offset);
  image.sense = shapes_->sense_radius > 0.0f
                    ? make_fixture(body_, agent_, FixtureRole::Sense, shapes_->sense_radius, offset)
                    : nullptr;
}

void PeriodicBody::remove_image(int index) {
  Image& image = images_[index];
  // Destroying a fixture ends its touching contacts (the listener sees EndContact).
  for (b2Fixture* f : {image.solid, image.detect, image.sense}) {
    if (f != nullptr) body_->DestroyFixture(f);
  }
  images_[index] = images_[count_ - 1];
  --count_;
}

void PeriodicBody::follow_torus() {
  if (!shapes_->torus) return;
  const b2Vec2 p = body_->GetPosition();
  const float m = shapes_->sensor_add_margin;
  if (count_ == 1 && p.x >= m && p.x <= shapes_->width - m && p.y >= m &&
      p.y <= shapes_->height - m) {
    return;  // in the interior with its own fixtures only: the common case
  }
  wrap();
  update_images();
}

void PeriodicBody::wrap() {
  b2Vec2 p = body_->GetPosition();
  const float w = shapes_->width;
  const float h = shapes_->height;
  int sx = 0;
  int sy = 0;
  if (p.x < 0.0f) {
    sx = 1;
    p.x += w;
    if (p.x >= w) p.x = std::nextafter(w, 0.0f);
  } else if (p.x >= w) {
    sx = -1;
    p.x -= w;
  }
  if (p.y < 0.0f) {
    sy = 1;
    p.y += h;
    if (p.y >= h) p.y = std::nextafter(h, 0.0f);
  } else if (p.y >= h) {
    sy = -1;
    p.y -= h;
  }
  if (sx == 0 && sy == 0) return;
  for (int k = 0; k < count_; ++k) {
    images_[k].ix = static_cast<std::int8_t>(images_[k].ix - sx);
    images_[k].iy = static_cast<std::int8_t>(images_[k].iy - sy);
    place(images_[k]);
  }
  body_->SetTransform(p, 0.0f);  // keeps the velocity; re-synchronises every proxy
}

void PeriodicBody::update_images() {
  const b2Vec2 p = body_->GetPosition();
  const float w = shapes_->width;
  const float h = shapes_->height;
  bool destroyed = false;
  // Images (sensors): drop those beyond the keep margin, add those within the add margin.
  const int keep_x = near_side(p.x, w, shapes_->sensor_keep_margin);
  const int keep_y = near_side(p.y, h, shapes_->sensor_keep_margin);
  for (int k = count_ - 1; k >= 0; --k) {
    const Image& image = images_[k];
    if ((image.ix == 0 && image.iy == 0) || image_fits(image.ix, image.iy, keep_x, keep_y)) {
      continue;
    }
    remove_image(k);
    destroyed = true;
  }
  if (!has_image(0, 0)) add_image(0, 0);  // cannot happen: a wrap stays within the margins
  const int add_x = near_side(p.x, w, shapes_->sensor_add_margin);
  const int add_y = near_side(p.y, h, shapes_->sensor_add_margin);
  if (add_x != 0 && !has_image(add_x, 0)) add_image(add_x, 0);
  if (add_y != 0 && !has_image(0, add_y)) add_image(0, add_y);
  if (add_x != 0 && add_y != 0 && !has_image(add_x, add_y)) add_image(add_x, add_y);
  // Solid discs of the images, in their own narrower band (2r reach instead of R).
  const int solid_keep_x = near_side(p.x, w, shapes_->solid_keep_margin);
  const int solid_keep_y = near_side(p.y, h, shapes_->solid_keep_margin);
  const int solid_add_x = near_side(p.x, w, shapes_->solid_add_margin);
  const int solid_add_y = near_side(p.y, h, shapes_->solid_add_margin);
  for (int k = 0; k < count_; ++k) {
    Image& image = images_[k];
    const bool own = image.ix == 0 && image.iy == 0;
    if (image.solid != nullptr && !own &&
        !image_fits(image.ix, image.iy, solid_keep_x, solid_keep_y)) {
      body_->DestroyFixture(image.solid);
      image.solid = nullptr;
      destroyed = true;
    } else if (image.solid == nullptr &&
               (own || image_fits(image.ix, image.iy, solid_add_x, solid_add_y))) {
      image.solid =
          make_fixture(body_, agent_, FixtureRole::Solid, shapes_->solid_radius, offset_of(image));
    }
  }
  if (destroyed) fix_mass();  // DestroyFixture recomputed the mass from the (zero) densities
}

void PeriodicBody::refilter_solids() {
  for (int k = 0; k < count_; ++k) {
    if (images_[k].solid != nullptr) images_[k].solid->Refilter();
  }
}

}  // namespace swarmagg::box2d
