#pragma once

// What the wide (SIMD) kernels share: kWideLanes solver bodies gathered into one register per
// field and scattered back, and the small vector helpers. Included by the wide kernels' files
// only (contact_kernels_wide.cpp, pin_rows_wide.cpp, revolute_rows_wide.cpp), each compiled for
// x86-64-v4, AVX2 and baseline x86-64 and picked at load time; the helpers are always inlined into
// those clones. The registers stay eight floats wide: what x86-64-v4 (AVX-512) brings is twice the
// vector registers, so the solve's temporaries stay out of the stack.

#include <cstddef>

#include "contact_kernels.hpp"

// The wide helpers pass vectors by value between internal functions only; the ABI note GCC
// gives for AVX-sized vectors without AVX enabled does not concern them.
#pragma GCC diagnostic ignored "-Wpsabi"

// The load-time pick runs before ThreadSanitizer's runtime is up, and its instrumented
// resolver would crash there: a ThreadSanitizer build keeps the baseline kernels only.
#if defined(__SANITIZE_THREAD__)
#define MINK_WIDE_KERNEL
#else
#define MINK_WIDE_KERNEL __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#endif

// Always inlined: a call out of a wider clone into a baseline copy would pass the vectors in
// another way than the clone expects.
#define MINK_WIDE_INLINE __attribute__((always_inline)) inline

namespace mink::detail {

struct WideBody {
  Wide vx, vy, w, turn, dpx, dpy, qc, qs;  // a solver body's fields, in its order
};

MINK_WIDE_INLINE Wide splat(SolverReal x) {
  return x - Wide{};
}
MINK_WIDE_INLINE Wide wmax(Wide a, Wide b) {
  return a > b ? a : b;
}
MINK_WIDE_INLINE Wide wmin(Wide a, Wide b) {
  return a < b ? a : b;
}

// A body's solver record is one register wide; kWideLanes of them side by side are a square
// matrix whose transpose holds one field per register.
static_assert(sizeof(SolverBody) == sizeof(Wide));
typedef std::int32_t WideIndex __attribute__((vector_size(32)));

// Lanes of two vectors picked by constant indices (b's lanes count from kWideLanes): GCC's
// __builtin_shuffle, which clang spells __builtin_shufflevector.
#if defined(__clang__)
#define MINK_SHUFFLE2(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)
#else
#define MINK_SHUFFLE2(a, b, ...) __builtin_shuffle(a, b, WideIndex{__VA_ARGS__})
#endif

MINK_WIDE_INLINE Wide load_row(const SolverBody& b) {
  Wide row;
  __builtin_memcpy(&row, &b, sizeof row);
  return row;
}

// The 8 x 8 transpose of single-precision rows, in three rounds of shuffles that stay within
// the rules of AVX2's in-lane unpacks and 128-bit permutes. Its own inverse.
MINK_WIDE_INLINE void transpose8(Wide (&m)[8]) {
  if constexpr (kWideLanes == 8) {
    Wide t[8], u[8];
    for (int i = 0; i < 8; i += 2) {
      t[i] = MINK_SHUFFLE2(m[i], m[i + 1], 0, 8, 1, 9, 4, 12, 5, 13);
      t[i + 1] = MINK_SHUFFLE2(m[i], m[i + 1], 2, 10, 3, 11, 6, 14, 7, 15);
    }
    for (int i = 0; i < 8; i += 4) {
      u[i] = MINK_SHUFFLE2(t[i], t[i + 2], 0, 1, 8, 9, 4, 5, 12, 13);
      u[i + 1] = MINK_SHUFFLE2(t[i], t[i + 2], 2, 3, 10, 11, 6, 7, 14, 15);
      u[i + 2] = MINK_SHUFFLE2(t[i + 1], t[i + 3], 0, 1, 8, 9, 4, 5, 12, 13);
      u[i + 3] = MINK_SHUFFLE2(t[i + 1], t[i + 3], 2, 3, 10, 11, 6, 7, 14, 15);
    }
    for (int i = 0; i < 4; ++i) {
      m[i] = MINK_SHUFFLE2(u[i], u[i + 4], 0, 1, 2, 3, 8, 9, 10, 11);
      m[i + 4] = MINK_SHUFFLE2(u[i], u[i + 4], 4, 5, 6, 7, 12, 13, 14, 15);
    }
  }
}

// Within each 128-bit half, the 4 x 4 transpose of four registers: registers of one field
// each become registers holding a row of lane k in the low half and of lane k + 4 in the
// high half, and back (it is its own inverse).
MINK_WIDE_INLINE void transpose4_halves(Wide (&m)[4]) {
  const Wide t0 = MINK_SHUFFLE2(m[0], m[1], 0, 8, 1, 9, 4, 12, 5, 13);
  const Wide t1 = MINK_SHUFFLE2(m[0], m[1], 2, 10, 3, 11, 6, 14, 7, 15);
  const Wide t2 = MINK_SHUFFLE2(m[2], m[3], 0, 8, 1, 9, 4, 12, 5, 13);
  const Wide t3 = MINK_SHUFFLE2(m[2], m[3], 2, 10, 3, 11, 6, 14, 7, 15);
  m[0] = MINK_SHUFFLE2(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
  m[1] = MINK_SHUFFLE2(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
  m[2] = MINK_SHUFFLE2(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
  m[3] = MINK_SHUFFLE2(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
}

// Half a body row: the velocities and the turn.
typedef SolverReal Half __attribute__((vector_size(16)));

MINK_WIDE_INLINE WideBody gather(const SolverBody* bodies, const std::int32_t* index) {
  WideBody w;
  if constexpr (kWideLanes == 8) {
    Wide m[8];
    for (int lane = 0; lane < 8; ++lane) m[lane] = load_row(bodies[index[lane]]);
    transpose8(m);
    w = {m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]};
  } else {
    for (int lane = 0; lane < kWideLanes; ++lane) {
      const SolverBody& b = bodies[index[lane]];
      w.vx[lane] = b.vx;
      w.vy[lane] = b.vy;
      w.w[lane] = b.w;
      w.turn[lane] = b.turn;
      w.dpx[lane] = b.dpx;
      w.dpy[lane] = b.dpy;
      w.qc[lane] = b.qc;
      w.qs[lane] = b.qs;
    }
  }
  return w;
}

// The rows' first halves (velocities and turn), for kernels that read no position: half the
// loads, a third of the shuffles.
MINK_WIDE_INLINE WideBody gather_velocities(const SolverBody* bodies, const std::int32_t* index) {
  WideBody w{};
  if constexpr (kWideLanes == 8) {
    Half halves[8];
    for (int lane = 0; lane < 8; ++lane) {
      __builtin_memcpy(&halves[lane], &bodies[index[lane]], sizeof(Half));
    }
    // Lanes k and k + 4 side by side, then the transpose within each half.
    Wide m[4];
    for (int k = 0; k < 4; ++k) {
      m[k] = __builtin_shufflevector(halves[k], halves[k + 4], 0, 1, 2, 3, 4, 5, 6, 7);
    }
    transpose4_halves(m);
    w.vx = m[0];
    w.vy = m[1];
    w.w = m[2];
    w.turn = m[3];
  } else {
    w = gather(bodies, index);  // without AVX-sized rows, the whole gather
  }
  return w;
}

// Only velocities change while solving, and only those of bodies the solver can move: a
// kinematic body or the still body (no inverse mass or inertia) may sit in several
// constraints of a colour, which other threads solve at the same time, so it is never
// written. A movable body is in one lane of a colour only. The row's first half (velocities
// and the turn, unchanged) goes back whole: transposing four fields rather than eight takes a
// third of the shuffles, and the position fields need not stay in registers until the end.
// `written(lane)` says which lanes go back.
template <typename Written>
MINK_WIDE_INLINE void scatter_where(SolverBody* bodies, const std::int32_t* index,
                                    const WideBody& w, Written written) {
  static_assert(offsetof(SolverBody, vx) == 0 && offsetof(SolverBody, turn) == 12);
  if constexpr (kWideLanes == 8) {
    Wide rows[4] = {w.vx, w.vy, w.w, w.turn};
    transpose4_halves(rows);
    // Unrolled, so each half is stored straight from its register.
#pragma GCC unroll 8
    for (int lane = 0; lane < 8; ++lane) {
      if (!written(lane)) continue;
      const Wide& row = rows[lane % 4];
      const Half half = lane < 4 ? __builtin_shufflevector(row, row, 0, 1, 2, 3)
                                 : __builtin_shufflevector(row, row, 4, 5, 6, 7);
      __builtin_memcpy(static_cast<void*>(&bodies[index[lane]]), &half, sizeof half);
    }
  } else {
    for (int lane = 0; lane < kWideLanes; ++lane) {
      if (!written(lane)) continue;
      SolverBody& b = bodies[index[lane]];
      b.vx = w.vx[lane];
      b.vy = w.vy[lane];
      b.w = w.w[lane];
    }
  }
}

// The joints' scatter: every lane in use (a joint has its own copy of a body the solver cannot
// move, so no two lanes of a colour share one).
MINK_WIDE_INLINE void scatter_lanes(SolverBody* bodies, const std::int32_t* index,
                                    const WideBody& w, std::int32_t lanes) {
  scatter_where(bodies, index, w, [&](int lane) { return lane < lanes; });
}

// The contacts' scatter: every lane whose body the solver can move.
MINK_WIDE_INLINE void scatter(SolverBody* bodies, const std::int32_t* index, const WideBody& w,
                              const Wide& inv_mass, const Wide& inv_inertia) {
  scatter_where(bodies, index, w,
                [&](int lane) { return inv_mass[lane] != 0 || inv_inertia[lane] != 0; });
}

}  // namespace mink::detail
