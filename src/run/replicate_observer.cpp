#include "run/replicate_observer.hpp"

#include <utility>

namespace swarmagg {

ObserverFactory both_observers(ObserverFactory first, ObserverFactory second) {
  if (!first) return second;
  if (!second) return first;
  return [first = std::move(first),
          second = std::move(second)](int index) -> std::unique_ptr<ReplicateObserver> {
    auto a = first(index);
    auto b = second(index);
    if (!a) return b;
    if (!b) return a;
    auto group = std::make_unique<ObserverGroup>();
    group->add(std::move(a));
    group->add(std::move(b));
    return group;
  };
}

}  // namespace swarmagg
