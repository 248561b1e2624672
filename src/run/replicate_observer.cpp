#include "run/replicate_observer.hpp"

#include <utility>

namespace swarmagg {
namespace {

class ObserverPair final : public ReplicateObserver {
 public:
  ObserverPair(std::unique_ptr<ReplicateObserver> first, std::unique_ptr<ReplicateObserver> second)
      : first_(std::move(first)), second_(std::move(second)) {}

  void observe(const Replicate& replicate) override {
    first_->observe(replicate);
    second_->observe(replicate);
  }
  void finish() override {
    first_->finish();
    second_->finish();
  }

 private:
  std::unique_ptr<ReplicateObserver> first_;
  std::unique_ptr<ReplicateObserver> second_;
};

}  // namespace

ObserverFactory both_observers(ObserverFactory first, ObserverFactory second) {
  if (!first) return second;
  if (!second) return first;
  return [first = std::move(first),
          second = std::move(second)](int index) -> std::unique_ptr<ReplicateObserver> {
    auto a = first(index);
    auto b = second(index);
    if (!a) return b;
    if (!b) return a;
    return std::make_unique<ObserverPair>(std::move(a), std::move(b));
  };
}

}  // namespace swarmagg
