// Vectors of N lanes for the fast paths' kernels, with the compiler's vector extensions (GCC
// and Clang). N is kernelLanes() (core/multiversion.h): eight, or four with the baseline's
// 16-byte registers. The helpers are always inlined into the kernels' builds, so no vector is
// passed between functions: the warning about the AVX calling convention does not apply,
// here or in the kernel files that include this one.
#pragma once
#pragma GCC diagnostic ignored "-Wpsabi"

#include <cstdint>

#define RL_LANES inline __attribute__((always_inline))

namespace rl::lanes {

template <int N>
struct LaneTypes;
template <>
struct LaneTypes<8> {
    typedef double Doubles __attribute__((vector_size(64)));
    typedef float Floats __attribute__((vector_size(32)));
    typedef std::int32_t Ints __attribute__((vector_size(32)));
};
template <>
struct LaneTypes<4> {
    typedef double Doubles __attribute__((vector_size(32)));
    typedef float Floats __attribute__((vector_size(16)));
    typedef std::int32_t Ints __attribute__((vector_size(16)));
};
typedef std::uint64_t Words2 __attribute__((vector_size(16)));

// Lanes where mask is set (all ones) take a, the others (zero) b.
template <class Floats, class Ints>
RL_LANES Floats select(const Ints& mask, const Floats& a, const Floats& b) {
    return reinterpret_cast<Floats>((mask & reinterpret_cast<Ints>(a)) |
                                    (~mask & reinterpret_cast<Ints>(b)));
}

// A mask's lanes folded into two 64-bit words, ANDed (both) and ORed (either): whether every
// lane is set, whether any is.
template <class Ints>
RL_LANES void foldMask(const Ints& mask, Words2& both, Words2& either) {
    if constexpr (sizeof(Ints) == 32) {
        typedef std::int32_t Ints4 __attribute__((vector_size(16)));
        const Ints4 low = __builtin_shufflevector(mask, mask, 0, 1, 2, 3);
        const Ints4 high = __builtin_shufflevector(mask, mask, 4, 5, 6, 7);
        both = reinterpret_cast<Words2>(low & high);
        either = reinterpret_cast<Words2>(low | high);
    } else {
        both = either = reinterpret_cast<Words2>(mask);
    }
}

}  // namespace rl::lanes
