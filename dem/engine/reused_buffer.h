#pragma once
// Buffers of the step loop that keep their storage from step to step (docs/dem.md,
// "Performance": the step loop allocates nothing once a bed's buffers have grown to its size).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace wear::dem {

/// Room for n elements in v, a quarter more when it has to grow: std::vector's assign(),
/// reserve() and a resize() or insert() from a small size allocate exactly what is asked, so a
/// count that wanders about a level (pairs, ghosts, near-wall particles, cells) would
/// reallocate each time it passes its last maximum.
template <class T>
void reserve_reusing(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity())
    v.reserve(n + n / 4);
}

/// Resizes v to n elements with reserve_reusing(); new elements are value-initialised, the
/// others keep their values.
template <class T>
void resize_reusing(std::vector<T>& v, std::size_t n) {
  reserve_reusing(v, n);
  v.resize(n);
}

/// resize_reusing(), every element then set to `value`.
template <class T>
void assign_reusing(std::vector<T>& v, std::size_t n, const T& value) {
  resize_reusing(v, n);
  std::fill(v.begin(), v.end(), value);
}

} // namespace wear::dem
