#pragma once
// An open-addressing hash map from 64-bit keys to small values. The grid's
// sparse vertex and cell maps sit on hot paths where std::unordered_map's node
// allocations dominate; this one stores slots in one array and clears in place.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace amls {

template <typename Value>
class FlatHashMap {
 public:
  // No grid key takes this value (see Grid::key).
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  explicit FlatHashMap(std::size_t expected = 16) { rehash(capacity_for(expected)); }

  std::size_t size() const { return size_; }

  void clear() {
    for (auto& slot : slots_) slot.key = kEmpty;
    size_ = 0;
  }

  void reserve(std::size_t expected) {
    const std::size_t needed = capacity_for(expected);
    if (needed > slots_.size()) rehash(needed);
  }

  Value* find(std::uint64_t key) {
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.key == key) return &s.value;
      if (s.key == kEmpty) return nullptr;
    }
  }
  const Value* find(std::uint64_t key) const { return const_cast<FlatHashMap*>(this)->find(key); }

  // Returns the value for `key`, default-constructing it first if absent;
  // the flag says whether it was inserted.
  std::pair<Value*, bool> try_emplace(std::uint64_t key) {
    if ((size_ + 1) * 2 > slots_.size()) rehash(slots_.size() * 2);
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.key == key) return {&s.value, false};
      if (s.key == kEmpty) {
        s.key = key;
        s.value = Value{};
        ++size_;
        return {&s.value, true};
      }
    }
  }

  template <typename Fn>
  void for_each(Fn&& fn) const {
    for (const Slot& s : slots_)
      if (s.key != kEmpty) fn(s.key, s.value);
  }

 private:
  struct Slot {
    std::uint64_t key = kEmpty;
    Value value{};
  };

  static std::size_t capacity_for(std::size_t expected) {
    std::size_t c = 16;
    while (c < expected * 2) c *= 2;
    return c;
  }

  // splitmix64's finalizer: neighbouring grid keys differ in few bits.
  std::size_t home(std::uint64_t k) const {
    k ^= k >> 30;
    k *= 0xbf58476d1ce4e5b9ULL;
    k ^= k >> 27;
    k *= 0x94d049bb133111ebULL;
    k ^= k >> 31;
    return static_cast<std::size_t>(k) & mask_;
  }

  void rehash(std::size_t capacity) {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    size_ = 0;
    for (Slot& s : old)
      if (s.key != kEmpty) *try_emplace(s.key).first = std::move(s.value);
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace amls
