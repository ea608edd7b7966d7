// x^n for the specular terms, as exp2(n log2(x)) with polynomials of our own: the same
// bits on every path, and made of operations a compiler can run on several lanes at once
// (std::pow cannot be vectorized without -ffast-math). The relative error is about 2e-7,
// growing with |n log2 x| as float's own rounding of that product does (1.9e-5 at worst for
// n up to 200 over 5 million random x in [0, 1]): a hundredth of a level at most in 0..255.
//   log2: x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(t), t = (m - 1)/(m + 1),
//         by its series up to t^9 (|t| <= 0.172: the next term is below 4e-10);
//   exp2: y = k + f with k whole and |f| <= 1/2; 2^f = e^(f ln 2) by its series up to the
//         7th power (the next term is below 4e-9); 2^k goes into the exponent bits.
// pow(0, n) is 1 for n = 0 and 0 for n > 0 (as C's pow); x must not be negative.
#pragma once

#include <bit>
#include <cstdint>

namespace rl {

// The two polynomials, for a float or a vector of floats (phong_kernel.cpp), so that every
// path evaluates them with the same operations.
// log2 m for t = (m - 1)/(m + 1):
template <typename F>
inline __attribute__((always_inline)) F log2FromT(const F& t) {
    const F t2 = t * t;
    const F series =
        1.0f + t2 * (1.0f / 3.0f + t2 * (1.0f / 5.0f + t2 * (1.0f / 7.0f + t2 * (1.0f / 9.0f))));
    return (2.0f * t * series) * 1.44269504f;  // ln m / ln 2
}
// 2^f for |f| <= 1/2:
template <typename F>
inline __attribute__((always_inline)) F exp2Fraction(const F& f) {
    const F u = f * 0.693147181f;
    return 1.0f +
           u * (1.0f + u * (0.5f + u * (1.0f / 6.0f +
                                        u * (1.0f / 24.0f +
                                             u * (1.0f / 120.0f +
                                                  u * (1.0f / 720.0f + u * (1.0f / 5040.0f)))))));
}

inline float fastLog2(float x) {
    const auto bits = std::bit_cast<std::uint32_t>(x < 1.17549435e-38f ? 1.17549435e-38f : x);
    float e = static_cast<float>(static_cast<int>(bits >> 23) - 127);
    float m = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);  // [1, 2)
    const bool high = m > 1.41421356f;
    m = high ? m * 0.5f : m;
    e = high ? e + 1.0f : e;
    return e + log2FromT((m - 1.0f) / (m + 1.0f));
}

inline float fastExp2(float y) {
    const bool underflow = y < -126.0f;
    y = y < -126.0f ? -126.0f : (y > 127.0f ? 127.0f : y);
    // k = floor(y + 1/2) through a conversion of a positive number (truncation = floor).
    const int k = static_cast<int>(y + 128.5f) - 128;
    const float p = exp2Fraction(y - static_cast<float>(k));  // y - k in [-1/2, 1/2]
    const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(k + 127) << 23);
    return underflow ? 0.0f : p * scale;
}

inline float fastPow(float x, float n) {
    const float power = fastExp2(n * fastLog2(x));
    return x > 0.0f ? power : (n == 0.0f ? 1.0f : 0.0f);
}

}  // namespace rl
