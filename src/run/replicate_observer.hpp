#pragma once
// Something that watches one replicate as it runs (a frame recorder, say). It only reads.
#include <functional>
#include <memory>
#include <vector>

namespace swarmagg {

class Replicate;

class ReplicateObserver {
 public:
  virtual ~ReplicateObserver() = default;
  virtual void observe(const Replicate& replicate) = 0;  // after setup and after each step
  virtual void finish() {}
};

// Several observers of one replicate, called in the order they were added.
class ObserverGroup final : public ReplicateObserver {
 public:
  void add(std::unique_ptr<ReplicateObserver> observer) {
    if (observer) observers_.push_back(std::move(observer));
  }
  void observe(const Replicate& replicate) override {
    for (const auto& o : observers_) o->observe(replicate);
  }
  void finish() override {
    for (const auto& o : observers_) o->finish();
  }

 private:
  std::vector<std::unique_ptr<ReplicateObserver>> observers_;
};

// Makes the observer of replicate `index`, or nullptr for none.
using ObserverFactory = std::function<std::unique_ptr<ReplicateObserver>(int index)>;

// Both factories' observers on each replicate (in that order); either may be empty.
ObserverFactory both_observers(ObserverFactory first, ObserverFactory second);

}  // namespace swarmagg
