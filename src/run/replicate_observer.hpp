#pragma once
// Something that watches one replicate as it runs (a frame recorder, say). It only reads.
#include <functional>
#include <memory>

namespace swarmagg {

class Replicate;

class ReplicateObserver {
 public:
  virtual ~ReplicateObserver() = default;
  virtual void observe(const Replicate& replicate) = 0;  // after setup and after each step
  virtual void finish() {}
};

// Makes the observer of replicate `index`, or nullptr for none.
using ObserverFactory = std::function<std::unique_ptr<ReplicateObserver>(int index)>;

// Both factories' observers on each replicate (in that order); either may be empty.
ObserverFactory both_observers(ObserverFactory first, ObserverFactory second);

}  // namespace swarmagg
