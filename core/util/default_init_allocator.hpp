#pragma once
// An allocator whose containers default-initialise the items they add without
// arguments (resize) instead of value-initialising them. For an item type
// without constructors that leaves the memory as it is: a vector kept between
// steps and resized to the step's length costs nothing per item, where
// value-initialisation would zero every added item on one thread before the
// parallel loop that fills them.
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace amls {

template <typename T, typename Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
  using Traits = std::allocator_traits<Base>;

 public:
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };

  using Base::Base;

  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

}  // namespace amls
