/* The vectorised sweep's range kernel with AVX2 and FMA: four candidates at a time. The
 * operations per lane are those of sph_force_cells_avx512.h in the same order, so the sums
 * get the pair list's bits (sph_force_cells.c). AVX2 has no mask registers: a mask is kept
 * as four bits, turned into a lane vector by a table for the blends; the loads and stores
 * are whole vectors (lanes out of the mask compute values nobody keeps, and the partners'
 * sums there are written back as they were), and a particle's own terms are packed into its
 * buffer by a permutation table in place of AVX-512's compress. */
#ifndef DMHS_SPH_FORCE_CELLS_AVX2_H
#define DMHS_SPH_FORCE_CELLS_AVX2_H
#include <immintrin.h>
#include <stdint.h>
#include <string.h>
#include "sph_force_cells_range.h"

/* bit l of the index -> all ones in 64-bit lane l */
#define AVX2_LANES(m)                                                                              \
  {                                                                                                \
    -(int64_t)((m)&1), -(int64_t)((m) >> 1 & 1), -(int64_t)((m) >> 2 & 1),                         \
        -(int64_t)((m) >> 3 & 1)                                                                   \
  }
static const int64_t avx2_lane_table[16][4] __attribute__((aligned(32))) = {
    AVX2_LANES(0),  AVX2_LANES(1),  AVX2_LANES(2),  AVX2_LANES(3),  AVX2_LANES(4),  AVX2_LANES(5),
    AVX2_LANES(6),  AVX2_LANES(7),  AVX2_LANES(8),  AVX2_LANES(9),  AVX2_LANES(10), AVX2_LANES(11),
    AVX2_LANES(12), AVX2_LANES(13), AVX2_LANES(14), AVX2_LANES(15),
};
#undef AVX2_LANES

/* the 32-bit halves of the lanes set in the index, packed to the front (the rest: lane 0) */
#define P2(l) 2 * (l), 2 * (l) + 1
static const int32_t avx2_pack_table[16][8] __attribute__((aligned(32))) = {
    {P2(0), P2(0), P2(0), P2(0)}, {P2(0), P2(0), P2(0), P2(0)}, {P2(1), P2(0), P2(0), P2(0)},
    {P2(0), P2(1), P2(0), P2(0)}, {P2(2), P2(0), P2(0), P2(0)}, {P2(0), P2(2), P2(0), P2(0)},
    {P2(1), P2(2), P2(0), P2(0)}, {P2(0), P2(1), P2(2), P2(0)}, {P2(3), P2(0), P2(0), P2(0)},
    {P2(0), P2(3), P2(0), P2(0)}, {P2(1), P2(3), P2(0), P2(0)}, {P2(0), P2(1), P2(3), P2(0)},
    {P2(2), P2(3), P2(0), P2(0)}, {P2(0), P2(2), P2(3), P2(0)}, {P2(1), P2(2), P2(3), P2(0)},
    {P2(0), P2(1), P2(2), P2(3)},
};
#undef P2

SPH_INLINE __m256i avx2_lanes(unsigned m) {
  return _mm256_load_si256((const __m256i *)avx2_lane_table[m]);
}
/* v in the lanes of m, the old values in the others (the slots' padding takes the lanes past
 * their end): AVX2's masked store is slow on some cores, a blend is not */
SPH_INLINE void avx2_store(double *p, __m256d old, unsigned m, __m256d v) {
  _mm256_storeu_pd(p, _mm256_blendv_pd(old, v, _mm256_castsi256_pd(avx2_lanes(m))));
}
/* the lanes of m, in lane order, to dst[0 ...]; writes four doubles */
SPH_INLINE void avx2_store_packed(double *dst, unsigned m, __m256d v) {
  const __m256i idx = _mm256_load_si256((const __m256i *)avx2_pack_table[m]);
  _mm256_storeu_pd(dst, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), idx)));
}
/* the bits of the lanes where a < b, of those in m */
SPH_INLINE unsigned avx2_less(unsigned m, __m256d a, __m256d b) {
  return m & (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_LT_OQ));
}
/* four flag bytes as 64-bit lanes */
SPH_INLINE __m256i avx2_flags(const unsigned char *fl) {
  int32_t bytes;
  memcpy(&bytes, fl, 4);
  return _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(bytes));
}
/* the bits of the lanes whose flags share a bit with k */
SPH_INLINE unsigned avx2_test(__m256i fb, __m256i k) {
  const __m256i none = _mm256_cmpeq_epi64(_mm256_and_si256(fb, k), _mm256_setzero_si256());
  return ~(unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(none)) & 0xFu;
}

/* Particle a of slot S against the candidates [first, last) of slot T. */
SPH_INLINE void cells_range(sph_kernel_kind kernel, int continuity, int artificial, int diffusion,
                            int same_v, const cells_args *A, const cells_slot *S, PetscInt a,
                            const cells_slot *T, PetscInt first, PetscInt last, own_sums *o) {
  /* the buffer's fill and the pair count in locals: read through o they would be read
   * again after every store (the intrinsics' stores may alias anything) */
  int n_buf = o->n;
  PetscInt64 pairs = o->pairs;
  const __m256d xa = _mm256_set1_pd(S->X[a]), ya = _mm256_set1_pd(S->Y[a]);
  const __m256d vxa = _mm256_set1_pd(S->VX[a]), vya = _mm256_set1_pd(S->VY[a]);
  const int read_est = (artificial || continuity) && !same_v; /* else EX, EY may not exist */
  const __m256d exa = read_est ? _mm256_set1_pd(S->EX[a]) : _mm256_setzero_pd();
  const __m256d eya = read_est ? _mm256_set1_pd(S->EY[a]) : _mm256_setzero_pd();
  const __m256d Pa = _mm256_set1_pd(S->P[a]), Ja = _mm256_set1_pd(S->J[a]);
  const __m256d Ma = _mm256_set1_pd(S->M[a]);
  /* 1/rho exists only for the density diffusion (cells_copy_scalars) */
  const __m256d MIRa = diffusion ? _mm256_set1_pd(S->M[a] * S->IR[a]) : _mm256_setzero_pd();
  const __m256d RHOa = diffusion || artificial ? _mm256_set1_pd(S->RHO[a]) : _mm256_setzero_pd();
  const unsigned fa = S->FL[a];
  const __m256i no_pair = _mm256_set1_epi64x(fa & FL_NO_PAIR);
  const __m256i wall_now = _mm256_set1_epi64x(FL_WALL_NOW);
  const __m256d h2 = _mm256_set1_pd(A->h2), r2_floor = _mm256_set1_pd(A->r2_floor);
  const __m256d inv_h = _mm256_set1_pd(A->inv_h), one = _mm256_set1_pd(1.0);
  const __m256d grad_norm = _mm256_set1_pd(A->grad_norm);
  const __m256d grad_norm_inv_h = _mm256_set1_pd(A->grad_norm_inv_h);
  const __m256d sign = _mm256_set1_pd(-0.0);
  for (PetscInt b = first; b < last; b += 4) {
    const unsigned tail = last - b >= 4 ? 0xFu : (1u << (last - b)) - 1u;
    const __m256d dx = _mm256_sub_pd(xa, _mm256_loadu_pd(T->X + b));
    const __m256d dy = _mm256_sub_pd(ya, _mm256_loadu_pd(T->Y + b));
    const __m256d r2 =
        _mm256_max_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), r2_floor);
    unsigned m = avx2_less(tail, r2, h2);
    if (!m)
      continue;
    const __m256i fb = avx2_flags(T->FL + b);
    if (fa & FL_NO_PAIR)
      m &= ~avx2_test(fb, no_pair);
    if ((fa & FL_SOLID) && A->excl) { /* the pair list's exclusions, lane by lane */
      unsigned both = m & avx2_test(fb, _mm256_set1_epi64x(FL_SOLID));
      while (both) {
        const int l = __builtin_ctz(both);
        both &= both - 1;
        if (topology_excluded(A->excl, A->ps, S->order[a], T->order[b + l]))
          m &= ~(1u << l);
      }
    }
    if (!m)
      continue;
    const __m256d r = _mm256_sqrt_pd(r2);
    /* sph_kernel_grad's g (1 - q)^k: (g - r g/h) (1 - r/h)^(k-1) */
    const __m256d mq = _mm256_fnmadd_pd(r, inv_h, one); /* 1 - q */
    __m256d grad = _mm256_mul_pd(_mm256_fnmadd_pd(r, grad_norm_inv_h, grad_norm), mq);
    if (kernel == SPH_KERNEL_WENDLAND)
      grad = _mm256_mul_pd(grad, mq);
    const __m256d Pb = _mm256_loadu_pd(T->P + b), Jb = _mm256_loadu_pd(T->J + b);
    const __m256d Mb = _mm256_loadu_pd(T->M + b);
    const __m256d press = _mm256_xor_pd(_mm256_add_pd(Pa, Pb), sign);
    const __m256d JJ = _mm256_mul_pd(Ja, Jb);
    const __m256d vvx = _mm256_sub_pd(vxa, _mm256_loadu_pd(T->VX + b));
    const __m256d vvy = _mm256_sub_pd(vya, _mm256_loadu_pd(T->VY + b));
    /* grad last (sph_force_iact.h): the brackets do not wait for the square root */
    __m256d T0 =
        _mm256_mul_pd(grad, _mm256_add_pd(_mm256_mul_pd(press, dx), _mm256_mul_pd(JJ, vvx)));
    __m256d T1 =
        _mm256_mul_pd(grad, _mm256_add_pd(_mm256_mul_pd(press, dy), _mm256_mul_pd(JJ, vvy)));
    __m256d vr = _mm256_setzero_pd(), RHOb = _mm256_setzero_pd();
    if (artificial || continuity) {
      /* same_v: no walls, v_est is v_visc (sph.c) */
      const __m256d vex = same_v ? vvx : _mm256_sub_pd(exa, _mm256_loadu_pd(T->EX + b));
      const __m256d vey = same_v ? vvy : _mm256_sub_pd(eya, _mm256_loadu_pd(T->EY + b));
      vr = _mm256_add_pd(_mm256_mul_pd(vex, dx), _mm256_mul_pd(vey, dy));
    }
    if (artificial || diffusion)
      RHOb = _mm256_loadu_pd(T->RHO + b);
    if (artificial) {
      const unsigned approaching = avx2_less(m, vr, _mm256_setzero_pd());
      if (approaching) {
        const __m256d mu = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(A->h), vr),
                                         _mm256_add_pd(r2, _mm256_set1_pd(A->av_h2)));
        const __m256d num =
            _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(A->neg_alpha_c0), mu),
                          _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(A->beta), mu), mu));
        const __m256d Pi =
            _mm256_div_pd(num, _mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_add_pd(RHOa, RHOb)));
        const __m256d pgav = _mm256_mul_pd(Pi, grad);
        const __m256d on = _mm256_castsi256_pd(avx2_lanes(approaching));
        T0 = _mm256_blendv_pd(T0, _mm256_sub_pd(T0, _mm256_mul_pd(pgav, dx)), on);
        T1 = _mm256_blendv_pd(T1, _mm256_sub_pd(T1, _mm256_mul_pd(pgav, dy)), on);
      }
    }
    /* the partners' sums, in place, each with one rounding (fused multiply-adds: the pair
     * list's partner update, sph_force.c) */
    double *AX = T->AX + b, *AY = T->AY + b;
    const __m256d ax = _mm256_loadu_pd(AX), ay = _mm256_loadu_pd(AY);
    avx2_store(AX, ax, m, _mm256_fnmadd_pd(Ma, T0, ax));
    avx2_store(AY, ay, m, _mm256_fnmadd_pd(Ma, T1, ay));
    /* a's own, buffered in partner order */
    avx2_store_packed(o->x + n_buf, m, _mm256_mul_pd(Mb, T0));
    avx2_store_packed(o->y + n_buf, m, _mm256_mul_pd(Mb, T1));
    if (continuity) {
      const __m256d q = _mm256_mul_pd(grad, vr);
      double *DR = T->DR + b;
      const __m256d dr_old = _mm256_loadu_pd(DR);
      __m256d dr = _mm256_fmadd_pd(Ma, q, dr_old);
      avx2_store_packed(o->q + n_buf, m, _mm256_mul_pd(Mb, q));
      if (diffusion) {
        /* walls' densities are extrapolated (sph_wall.c): no diffusion through them */
        const unsigned md = fa & FL_WALL_NOW ? 0u : m & ~avx2_test(fb, wall_now);
        const __m256d on = _mm256_castsi256_pd(avx2_lanes(md));
        const __m256d D =
            _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(A->two_dhc), _mm256_sub_pd(RHOb, RHOa)),
                          _mm256_xor_pd(grad, sign));
        dr = _mm256_blendv_pd(dr, _mm256_fnmadd_pd(MIRa, D, dr), on);
        /* a's diffusion term rides with its continuity term, packed by m like it so that
         * the buffers stay aligned: 0 where md is off, and adding 0 leaves a sum's bits as
         * the pair-list sweep that skips the term */
        const __m256d IRb = _mm256_loadu_pd(T->IR + b);
        const __m256d own_d = _mm256_and_pd(on, _mm256_mul_pd(_mm256_mul_pd(Mb, IRb), D));
        avx2_store_packed(o->d + n_buf, m, own_d);
      }
      avx2_store(DR, dr_old, m, dr);
    }
    n_buf += __builtin_popcount(m);
    pairs += __builtin_popcount(m);
    if (n_buf > SPH_CELLS_BUF - 4) {
      o->n = n_buf;
      own_flush(o, continuity, diffusion);
      n_buf = 0;
    }
  }
  o->n = n_buf;
  o->pairs = pairs;
}
#endif
