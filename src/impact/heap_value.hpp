// A value on the heap owned by one object and copied with it, for the members of a stepper that
// cannot live inside it (a table too large to move, a parser that binds variables by address).
//
// It exists for the step loop (simulate.hpp, simulate()): the loop steps a local copy of the
// stepper, whose members stay in registers only while no out-of-line call receives the local's
// address. A std::vector or std::unique_ptr member makes the stepper's destructor non-trivial, and
// GCC does not inline it on the loop's exception path (cold code), so that path calls it with the
// local's address and the whole stepper stays in memory: a harmonic direct step took 4.3 instead
// of 3.8 ns (AMD EPYC family 26 model 2; 1.75 with a constant force). Here every special member is
// inlined, and the one out-of-line call, the deletion, receives the heap pointer alone.
#pragma once

#include <memory>
#include <utility>

namespace impact {

template <class T>
class HeapValue {
 public:
  HeapValue() = default;
  explicit HeapValue(std::unique_ptr<T> value) : value_(value.release()) {}
  HeapValue(const HeapValue& other) : value_(other.value_ ? copy(*other.value_) : nullptr) {}
  [[gnu::always_inline]] HeapValue(HeapValue&& other) noexcept
      : value_(std::exchange(other.value_, nullptr)) {}
  [[gnu::always_inline]] HeapValue& operator=(HeapValue other) noexcept {
    std::swap(value_, other.value_);
    return *this;
  }
  [[gnu::always_inline]] ~HeapValue() {
    if (value_) destroy(value_);
  }

  explicit operator bool() const { return value_ != nullptr; }
  T& operator*() const { return *value_; }
  T* operator->() const { return value_; }

 private:
  [[gnu::noinline]] static T* copy(const T& value) { return new T(value); }
  [[gnu::noinline]] static void destroy(T* value) { delete value; }

  T* value_ = nullptr;
};

}  // namespace impact
