#pragma once
// A history the frames share (SharedSpan in contracts/frame_state.hpp): values are appended, the oldest dropped,
// and the whole rewritten (thinned), but storage a frame may refer to is never changed or moved. Appending into a
// full storage, or rewriting, goes on in new storage (the frames that refer to the old one keep it alive);
// dropping the oldest only moves the start. Each frame's view costs O(1), appending O(1) amortised.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "contracts/frame_state.hpp"

namespace sl {

template <class T>
class SharedTrack {
 public:
  std::size_t size() const { return store_ ? store_->size() - first_ : 0; }
  bool empty() const { return size() == 0; }
  const T& operator[](std::size_t i) const { return (*store_)[first_ + i]; }
  const T& back() const { return store_->back(); }
  const T* begin() const { return store_ ? store_->data() + first_ : nullptr; }
  const T* end() const { return begin() + size(); }

  void push_back(const T& value) {
    if (!store_ || store_->size() == store_->capacity()) restart(std::max<std::size_t>(64, 2 * (size() + 1)));
    store_->push_back(value);
  }
  // Drops the oldest `count` values.
  void dropOldest(std::size_t count) { first_ += std::min(count, size()); }
  // Replaces the values by `values` (in new storage).
  void assign(std::vector<T> values) {
    auto store = std::make_shared<std::vector<T>>();
    store->reserve(std::max<std::size_t>(64, 2 * values.size()));
    store->insert(store->end(), values.begin(), values.end());
    store_ = std::move(store);
    first_ = 0;
  }
  // The values now, for a frame.
  SharedSpan<T> view() const { return store_ ? SharedSpan<T>(store_, first_, size()) : SharedSpan<T>(); }

 private:
  // Goes on in new storage of `capacity`, holding the current values.
  void restart(std::size_t capacity) {
    auto store = std::make_shared<std::vector<T>>();
    store->reserve(capacity);
    store->insert(store->end(), begin(), end());
    store_ = std::move(store);
    first_ = 0;
  }

  std::shared_ptr<std::vector<T>> store_;
  std::size_t first_ = 0;
};

}  // namespace sl
