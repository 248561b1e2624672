#include "engine/box2d/contact_rules.hpp"

#include "engine/box2d/fixture_tags.hpp"

namespace swarmagg::box2d {

bool ContactRules::ShouldCollide(b2Fixture* a, b2Fixture* b) {
  // Box2D's own category test first (overriding the filter replaces it).
  const b2Filter& fa = a->GetFilterData();
  const b2Filter& fb = b->GetFilterData();
  if ((fa.maskBits & fb.categoryBits) == 0 || (fb.maskBits & fa.categoryBits) == 0) return false;
  const FixtureTag ta = tag_of(a);
  const FixtureTag tb = tag_of(b);
  if (ta.role == FixtureRole::Solid && tb.role == FixtureRole::Solid) {
    return controls_.solid(ta.agent, tb.agent);
  }
  return true;
}

void ContactRules::halt(AgentId agent) {
  if (controls_.halted[agent]) return;
  controls_.halted[agent] = 1;
  // Called from inside b2World::Step, between the contact update and the solver: the body
  // stops for the rest of this (sub)step already.
  bodies_[agent].body()->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
}

void ContactRules::BeginContact(b2Contact* contact) {
  const FixtureTag ta = tag_of(contact->GetFixtureA());
  const FixtureTag tb = tag_of(contact->GetFixtureB());
  if (ta.role != tb.role) return;
  if (ta.role == FixtureRole::Sense) {
    links_.begin(ta.agent, tb.agent, SensorKind::Sense);
    return;
  }
  if (ta.role != FixtureRole::Detect) return;
  if (!links_.begin(ta.agent, tb.agent, SensorKind::Detect) || !stepping_) return;
  ++encounters_;
  if (controls_.halt_on[ta.agent] & mask_of(controls_.signal[tb.agent])) halt(ta.agent);
  if (controls_.halt_on[tb.agent] & mask_of(controls_.signal[ta.agent])) halt(tb.agent);
}

void ContactRules::EndContact(b2Contact* contact) {
  const FixtureTag ta = tag_of(contact->GetFixtureA());
  const FixtureTag tb = tag_of(contact->GetFixtureB());
  if (ta.role != tb.role) return;
  if (ta.role == FixtureRole::Detect) links_.end(ta.agent, tb.agent, SensorKind::Detect);
  if (ta.role == FixtureRole::Sense) links_.end(ta.agent, tb.agent, SensorKind::Sense);
}

void ContactRules::PreSolve(b2Contact* contact, const b2Manifold* /*old_manifold*/) {
  b2Fixture* fa = contact->GetFixtureA();
  b2Fixture* fb = contact->GetFixtureB();
  const FixtureTag ta = tag_of(fa);
  const FixtureTag tb = tag_of(fb);
  if (ta.role != FixtureRole::Solid || tb.role != FixtureRole::Solid) return;
  // The representative of a pair is the fixture pair in which the lower-numbered agent
  // takes part with its own disc (the image at offset zero); there is exactly one.
  const b2Fixture* lower = ta.agent < tb.agent ? fa : fb;
  const b2Vec2 offset = static_cast<const b2CircleShape*>(lower->GetShape())->m_p;
  if (offset.x != 0.0f || offset.y != 0.0f) contact->SetEnabled(false);
}

}  // namespace swarmagg::box2d
