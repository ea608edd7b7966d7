// fast_pow.h's polynomials, included before lanes.h, are always inlined like its helpers: the
// AVX calling-convention warning does not apply to them either.
#pragma GCC diagnostic ignored "-Wpsabi"

#include "phong_kernel.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "pipeline/core/fast_pow.h"
#include "pipeline/core/multiversion.h"
#include "pipeline/fast/lanes.h"

namespace rl {

CoursePhongRun coursePhongRun(const Material& m, const ViewLight& light,
                              const vec3& ambientIntensity, bool flip) {
    CoursePhongRun run;
    run.ambient = ambientIntensity * m.ka;
    run.diffuse = light.intensity * m.od * m.kd;
    run.specular = light.intensity * m.ks;
    run.light = vec3(light.pView);
    run.directional = light.pView.w == 0.0;
    run.shininess = m.shininess;
    run.flip = flip;
    run.withSpecular = m.ks != 0.0f;
    return run;
}

namespace {

using namespace lanes;

// The helpers and kernels of one width, N lanes (lanes.h): each operation below is the
// scalar one of phong() applied to N pixels, so the results are the same bits at either
// width.
template <int N>
struct Lanes {
    static constexpr int kLanes = N;
    using Floats = typename LaneTypes<N>::Floats;
    using Ints = typename LaneTypes<N>::Ints;

    static RL_LANES Floats splat(float f) {
        if constexpr (N == 8)
            return Floats{f, f, f, f, f, f, f, f};
        else
            return Floats{f, f, f, f};
    }
    static RL_LANES Ints splat(std::int32_t i) {
        if constexpr (N == 8)
            return Ints{i, i, i, i, i, i, i, i};
        else
            return Ints{i, i, i, i};
    }
    // 0, 1, ..., N - 1.
    static RL_LANES Ints laneIndices() {
        if constexpr (N == 8)
            return Ints{0, 1, 2, 3, 4, 5, 6, 7};
        else
            return Ints{0, 1, 2, 3};
    }

    static RL_LANES Floats squareRoot(const Floats& v) {
        Floats r;
        for (int i = 0; i < kLanes; ++i) r[i] = __builtin_sqrtf(v[i]);  // correctly rounded
        return r;
    }

    // |v| lane by lane (the sign bit cleared, as std::abs), and std::max(a, b): a < b ? b : a.
    static RL_LANES Floats magnitude(const Floats& v) {
        return reinterpret_cast<Floats>(reinterpret_cast<Ints>(v) & splat(0x7fffffff));
    }
    static RL_LANES Floats larger(const Floats& a, const Floats& b) { return select(a < b, b, a); }

    // Whether any lane of a mask is set.
    static RL_LANES bool anyLane(const Ints& mask) {
        Words2 both, either;
        foldMask(mask, both, either);
        return (either[0] | either[1]) != 0;
    }

    // N (r, g, b) triples written as 3 N consecutive floats (three vector stores).
    static RL_LANES void storeInterleaved(const Floats& r, const Floats& g, const Floats& b,
                                          float* out) {
        Floats out0, out1, out2;
        if constexpr (N == 8) {
            const Floats rg0 = __builtin_shufflevector(r, g, 0, 8, 0, 1, 9, 1, 2, 10);
            const Floats rg1 = __builtin_shufflevector(r, g, 2, 3, 11, 3, 4, 12, 4, 5);
            const Floats rg2 = __builtin_shufflevector(r, g, 13, 5, 6, 14, 6, 7, 15, 7);
            out0 = __builtin_shufflevector(rg0, b, 0, 1, 8, 3, 4, 9, 6, 7);
            out1 = __builtin_shufflevector(rg1, b, 10, 1, 2, 11, 4, 5, 12, 7);
            out2 = __builtin_shufflevector(rg2, b, 0, 13, 2, 3, 14, 5, 6, 15);
        } else {
            const Floats rg = __builtin_shufflevector(r, g, 0, 4, 1, 5);   // r0 g0 r1 g1
            const Floats gb = __builtin_shufflevector(g, b, 1, 5, 2, 6);   // g1 b1 g2 b2
            const Floats rg3 = __builtin_shufflevector(r, g, 3, 7, 3, 7);  // r3 g3 r3 g3
            out0 = __builtin_shufflevector(rg, b, 0, 1, 4, 2);             // r0 g0 b0 r1
            out1 = __builtin_shufflevector(gb, r, 0, 1, 6, 2);             // g1 b1 r2 g2
            out2 = __builtin_shufflevector(rg3, b, 6, 0, 1, 7);            // b2 r3 g3 b3
        }
        std::memcpy(out, &out0, sizeof out0);
        std::memcpy(out + kLanes, &out1, sizeof out1);
        std::memcpy(out + 2 * kLanes, &out2, sizeof out2);
    }

    // N (beta, gamma) pairs from bary[0] on, split into betas and gammas (two loads).
    static RL_LANES void loadBarycentrics(const vec2* bary, Floats& beta, Floats& gamma) {
        Floats low, high;
        std::memcpy(&low, &bary[0].x, sizeof low);
        std::memcpy(&high, &bary[kLanes / 2].x, sizeof high);
        if constexpr (N == 8) {
            beta = __builtin_shufflevector(low, high, 0, 2, 4, 6, 8, 10, 12, 14);
            gamma = __builtin_shufflevector(low, high, 1, 3, 5, 7, 9, 11, 13, 15);
        } else {
            beta = __builtin_shufflevector(low, high, 0, 2, 4, 6);
            gamma = __builtin_shufflevector(low, high, 1, 3, 5, 7);
        }
    }

    // fast_pow.h's fastLog2, fastExp2 and fastPow, lane by lane.
    static RL_LANES Floats log2Lanes(const Floats& x) {
        const Floats smallest = splat(1.17549435e-38f);
        const Ints bits = reinterpret_cast<Ints>(select(x < smallest, smallest, x));
        Floats e = __builtin_convertvector((bits >> 23) - 127, Floats);  // bits is positive
        Floats m = reinterpret_cast<Floats>((bits & 0x007fffff) | 0x3f800000);
        const Ints high = m > splat(1.41421356f);
        m = select(high, m * 0.5f, m);
        e = select(high, e + 1.0f, e);
        return e + log2FromT<Floats>((m - 1.0f) / (m + 1.0f));
    }

    static RL_LANES Floats exp2Lanes(const Floats& exponent) {
        const Ints underflow = exponent < -126.0f;
        const Floats y =
            select(underflow, splat(-126.0f), select(exponent > 127.0f, splat(127.0f), exponent));
        const Ints k = __builtin_convertvector(y + 128.5f, Ints) - 128;
        const Floats p = exp2Fraction<Floats>(y - __builtin_convertvector(k, Floats));
        const Floats scale = reinterpret_cast<Floats>((k + 127) << 23);
        return select(underflow, splat(0.0f), p * scale);
    }

    static RL_LANES Floats powLanes(const Floats& x, float n) {
        const Floats power = exp2Lanes(n * log2Lanes(x));
        return select(x > 0.0f, power, splat(n == 0.0f ? 1.0f : 0.0f));
    }

    // The course's Phong model at the lanes' points P with (not normalised) normals N: the
    // operations of phong(), lane by lane, so the colours are the same bits.
    struct LitLanes {
        Floats r, g, b;
        Floats nx, ny, nz;  // the normal used (normalised, turned toward the viewer)
        Ints hasN, turn, behind, noSpecular;
    };

    static RL_LANES LitLanes lightLanes(const CoursePhongRun& run, const Floats& px,
                                        const Floats& py, const Floats& pz, Floats nx, Floats ny,
                                        Floats nz) {
        const Ints all = splat(-1), none = splat(0);
        const Ints flip = run.flip ? all : none;
        const Ints directional = run.directional ? all : none;
        const Ints withSpecular = run.withSpecular ? all : none;
        // V = -P'/|P'| (zero when P' is); N normalised; turned toward the viewer when V.N < 0.
        const Floats vLength = squareRoot((px * px + py * py) + pz * pz);
        const Ints hasV = vLength > 0.0f;
        const Floats vInverse = 1.0f / select(hasV, vLength, splat(1.0f));
        const Floats vx = select(hasV, -px * vInverse, splat(0.0f));
        const Floats vy = select(hasV, -py * vInverse, splat(0.0f));
        const Floats vz = select(hasV, -pz * vInverse, splat(0.0f));
        const Floats nLength = squareRoot((nx * nx + ny * ny) + nz * nz);
        const Ints hasN = nLength > 0.0f;
        const Floats nInverse = 1.0f / select(hasN, nLength, splat(1.0f));
        nx = nx * nInverse;
        ny = ny * nInverse;
        nz = nz * nInverse;
        const Ints turn = flip & (((vx * nx + vy * ny) + vz * nz) < 0.0f);
        nx = select(turn, -nx, nx);
        ny = select(turn, -ny, ny);
        nz = select(turn, -nz, nz);
        // L toward the light.
        Floats tx = select(directional, splat(run.light.x), run.light.x - px);
        Floats ty = select(directional, splat(run.light.y), run.light.y - py);
        Floats tz = select(directional, splat(run.light.z), run.light.z - pz);
        Floats lLength = squareRoot((tx * tx + ty * ty) + tz * tz);
        // A light so far that the square of its distance overflows: brought nearer along the
        // same line, as towardLight does.
        const Ints overflowed = lLength == std::numeric_limits<float>::infinity();
        if (anyLane(overflowed)) {
            const Floats largest = larger(larger(magnitude(tx), magnitude(ty)), magnitude(tz));
            const Floats shrink = 1.0f / largest;
            tx = select(overflowed, tx * shrink, tx);
            ty = select(overflowed, ty * shrink, ty);
            tz = select(overflowed, tz * shrink, tz);
            lLength = select(overflowed, squareRoot((tx * tx + ty * ty) + tz * tz), lLength);
        }
        const Ints hasL = lLength > 0.0f;
        const Floats lInverse = 1.0f / select(hasL, lLength, splat(1.0f));
        const Floats lx = tx * lInverse, ly = ty * lInverse, lz = tz * lInverse;
        const Floats nDotL = (nx * lx + ny * ly) + nz * lz;
        const Ints lit = hasN & hasL & (nDotL >= 0.0f);
        // R = 2 (N.L) N - L (a unit vector); R.V.
        const Floats twice = 2.0f * nDotL;
        const Floats rx = twice * nx - lx, ry = twice * ny - ly, rz = twice * nz - lz;
        const Floats rDotV = (rx * vx + ry * vy) + rz * vz;
        const Ints highlight = lit & withSpecular & (rDotV >= 0.0f);
        // No specular work at all when ks = 0, nor for lanes none of which has a
        // highlight (the light behind them, or R turned away from V).
        const Floats power =
            anyLane(highlight)
                ? select(highlight,
                         powLanes(select(rDotV > 0.0f, rDotV, splat(0.0f)), run.shininess),
                         splat(0.0f))
                : splat(0.0f);
        const Floats zero = splat(0.0f);
        // ((ambient + diffuse) + specular) + unlit (zero), as PhongSample::colour() adds them
        // (the last addition turns -0 into +0 there, so here too).
        LitLanes out;
        out.r = ((run.ambient.x + select(lit, run.diffuse.x * nDotL, zero)) +
                 select(highlight, run.specular.x * power, zero)) +
                0.0f;
        out.g = ((run.ambient.y + select(lit, run.diffuse.y * nDotL, zero)) +
                 select(highlight, run.specular.y * power, zero)) +
                0.0f;
        out.b = ((run.ambient.z + select(lit, run.diffuse.z * nDotL, zero)) +
                 select(highlight, run.specular.z * power, zero)) +
                0.0f;
        out.nx = nx;
        out.ny = ny;
        out.nz = nz;
        out.hasN = hasN;
        out.turn = turn;
        out.behind = hasN & hasL & (nDotL < 0.0f);
        out.noSpecular = lit & (rDotV < 0.0f);
        return out;
    }

    // Minus the counts of a kernel's lanes (a set lane is -1), added up at the end.
    struct LaneCounts {
        Ints flipped = splat(0), behind = splat(0), noSpecular = splat(0), noNormal = splat(0),
             clamped = splat(0);

        RL_LANES void add(const LitLanes& l, const Ints& valid) {
            flipped += valid & l.hasN & l.turn;
            behind += valid & l.behind;
            noSpecular += valid & l.noSpecular;
            noNormal += valid & ~l.hasN;
        }
        RL_LANES void addTo(CoursePhongCounts& counts) const {
            for (int i = 0; i < kLanes; ++i) {
                counts.flipped += static_cast<std::size_t>(-flipped[i]);
                counts.lightBehind += static_cast<std::size_t>(-behind[i]);
                counts.noSpecular += static_cast<std::size_t>(-noSpecular[i]);
                counts.noNormal += static_cast<std::size_t>(-noNormal[i]);
                counts.clamped += static_cast<std::size_t>(-clamped[i]);
            }
        }
    };

    static RL_LANES void phongRun(const CoursePhongRun& run, const vec2* bary, int count,
                                  vec3* colour, vec3* normal, float clampScale,
                                  CoursePhongCounts& counts) {
        const Ints laneIndex = laneIndices();
        LaneCounts sums;
        for (int start = 0; start < count; start += kLanes) {
            const int n = count - start < kLanes ? count - start : kLanes;
            Floats beta, gamma;
            if (n == kLanes) {
                loadBarycentrics(bary + start, beta, gamma);
            } else {
                for (int i = 0; i < kLanes; ++i) {  // lanes past the run repeat its first pixel
                    beta[i] = bary[start + (i < n ? i : 0)].x;
                    gamma[i] = bary[start + (i < n ? i : 0)].y;
                }
            }
            // P' and N, as interpolate() writes them: (a + beta d1) + gamma d2.
            const Floats px = (run.p0.x + beta * run.dp1.x) + gamma * run.dp2.x;
            const Floats py = (run.p0.y + beta * run.dp1.y) + gamma * run.dp2.y;
            const Floats pz = (run.p0.z + beta * run.dp1.z) + gamma * run.dp2.z;
            const Floats nx = (run.n0.x + beta * run.dn1.x) + gamma * run.dn2.x;
            const Floats ny = (run.n0.y + beta * run.dn1.y) + gamma * run.dn2.y;
            const Floats nz = (run.n0.z + beta * run.dn1.z) + gamma * run.dn2.z;
            const LitLanes l = lightLanes(run, px, py, pz, nx, ny, nz);
            const Ints valid = laneIndex < n;
            sums.add(l, valid);
            sums.clamped += valid & ((l.r > clampScale) | (l.g > clampScale) | (l.b > clampScale));
            if (n == kLanes) {
                storeInterleaved(l.r, l.g, l.b, &colour[start].x);
            } else {
                for (int i = 0; i < n; ++i) colour[start + i] = vec3(l.r[i], l.g[i], l.b[i]);
            }
            if (normal) {
                for (int i = 0; i < n; ++i)
                    normal[start + i] = l.hasN[i] ? vec3(l.nx[i], l.ny[i], l.nz[i]) : vec3(0.0f);
            }
        }
        sums.addTo(counts);
    }

    static RL_LANES void phongPoints(const CoursePhongRun& run, const vec3* p, const vec3* n,
                                     const std::uint32_t* at, std::size_t count, vec3* colour,
                                     vec3* normal, CoursePhongCounts& counts) {
        const Ints laneIndex = laneIndices();
        const auto point = [at](std::size_t i) { return at ? at[i] : i; };
        LaneCounts sums;
        for (std::size_t start = 0; start < count; start += kLanes) {
            const int used = count - start < kLanes ? static_cast<int>(count - start) : kLanes;
            Floats px, py, pz, nx, ny, nz;
            for (int i = 0; i < kLanes; ++i) {  // lanes past the list repeat its first point
                const std::size_t v = point(start + static_cast<std::size_t>(i < used ? i : 0));
                px[i] = p[v].x;
                py[i] = p[v].y;
                pz[i] = p[v].z;
                nx[i] = n[v].x;
                ny[i] = n[v].y;
                nz[i] = n[v].z;
            }
            const LitLanes l = lightLanes(run, px, py, pz, nx, ny, nz);
            sums.add(l, laneIndex < used);
            for (int i = 0; i < used; ++i) {
                const std::size_t v = point(start + static_cast<std::size_t>(i));
                colour[v] = vec3(l.r[i], l.g[i], l.b[i]);
                if (normal) normal[v] = l.hasN[i] ? vec3(l.nx[i], l.ny[i], l.nz[i]) : vec3(0.0f);
            }
        }
        sums.addTo(counts);
    }

    static RL_LANES std::size_t gouraudRun(const vec3& c0, const vec3& d1, const vec3& d2,
                                           const vec2* bary, int count, vec3* colour,
                                           float clampScale) {
        Ints clampedSum = splat(0);
        int start = 0;
        for (; start + kLanes <= count; start += kLanes) {
            Floats beta, gamma;
            loadBarycentrics(bary + start, beta, gamma);
            const Floats r = (c0.r + beta * d1.r) + gamma * d2.r;
            const Floats g = (c0.g + beta * d1.g) + gamma * d2.g;
            const Floats b = (c0.b + beta * d1.b) + gamma * d2.b;
            storeInterleaved(r, g, b, &colour[start].x);
            clampedSum += (r > clampScale) | (g > clampScale) | (b > clampScale);
        }
        std::size_t clamped = 0;
        for (int i = 0; i < kLanes; ++i) clamped += static_cast<std::size_t>(-clampedSum[i]);
        for (; start < count; ++start) {
            const float beta = bary[start].x, gamma = bary[start].y;
            const float r = (c0.r + beta * d1.r) + gamma * d2.r;
            const float g = (c0.g + beta * d1.g) + gamma * d2.g;
            const float b = (c0.b + beta * d1.b) + gamma * d2.b;
            colour[start] = vec3(r, g, b);
            clamped += ((r > clampScale) | (g > clampScale) | (b > clampScale)) ? 1u : 0u;
        }
        return clamped;
    }

    static RL_LANES void fillRun(const vec3& colour, int count, vec3* out) {
        const Floats r = splat(colour.r), g = splat(colour.g), b = splat(colour.b);
        int start = 0;
        for (; start + kLanes <= count; start += kLanes) storeInterleaved(r, g, b, &out[start].x);
        for (; start < count; ++start) out[start] = colour;
    }
};

}  // namespace

RL_MULTIVERSION void shadeCoursePhongRun(const CoursePhongRun& run, const vec2* bary, int count,
                                         vec3* colour, vec3* normal, float clampScale,
                                         CoursePhongCounts& counts) {
    if (kernelLanes() == 8)
        Lanes<8>::phongRun(run, bary, count, colour, normal, clampScale, counts);
    else
        Lanes<4>::phongRun(run, bary, count, colour, normal, clampScale, counts);
}

RL_MULTIVERSION void shadeCoursePhongPoints(const CoursePhongRun& run, const vec3* p, const vec3* n,
                                            const std::uint32_t* at, std::size_t count,
                                            vec3* colour, vec3* normal, CoursePhongCounts& counts) {
    if (kernelLanes() == 8)
        Lanes<8>::phongPoints(run, p, n, at, count, colour, normal, counts);
    else
        Lanes<4>::phongPoints(run, p, n, at, count, colour, normal, counts);
}

RL_MULTIVERSION std::size_t shadeGouraudRun(const vec3& c0, const vec3& d1, const vec3& d2,
                                            const vec2* bary, int count, vec3* colour,
                                            float clampScale) {
    if (kernelLanes() == 8)
        return Lanes<8>::gouraudRun(c0, d1, d2, bary, count, colour, clampScale);
    else
        return Lanes<4>::gouraudRun(c0, d1, d2, bary, count, colour, clampScale);
}

RL_MULTIVERSION void fillColourRun(const vec3& colour, int count, vec3* out) {
    if (kernelLanes() == 8)
        Lanes<8>::fillRun(colour, count, out);
    else
        Lanes<4>::fillRun(colour, count, out);
}

}  // namespace rl
