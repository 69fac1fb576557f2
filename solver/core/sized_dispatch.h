// One home for handing a small model's run-time size to code sized at compile time (its loops
// unrolled, without the vectoriser's alias and remainder tests, which cost more than the
// arithmetic on a few DOFs): SmallLlt, CompressedRows and the Newmark step.
#pragma once

#include <Eigen/Core>

namespace isopound {

inline constexpr int kMaxSizedDofs = 8;

// sized.template operator()<n>() for 1 <= n <= kMaxSizedDofs, sized.template operator()<0>()
// (the caller's run-time path) for any other n.
template <class Sized>
decltype(auto) dispatch_size(Eigen::Index n, Sized&& sized) {
  switch (n) {
    case 1:
      return sized.template operator()<1>();
    case 2:
      return sized.template operator()<2>();
    case 3:
      return sized.template operator()<3>();
    case 4:
      return sized.template operator()<4>();
    case 5:
      return sized.template operator()<5>();
    case 6:
      return sized.template operator()<6>();
    case 7:
      return sized.template operator()<7>();
    case 8:
      return sized.template operator()<8>();
    default:
      return sized.template operator()<0>();
  }
}

}  // namespace isopound
