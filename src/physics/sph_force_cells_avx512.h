/* The vectorised sweep's range kernel with AVX-512: eight candidates at a time, masks in
 * mask registers, a particle's own terms compressed into its buffer in partner order
 * (sph_force_cells.c says why this gives the pair list's bits). */
#ifndef DMHS_SPH_FORCE_CELLS_AVX512_H
#define DMHS_SPH_FORCE_CELLS_AVX512_H
#include <immintrin.h>
#include "sph_force_cells_range.h"

/* Particle a of slot S against the candidates [first, last) of slot T. */
SPH_INLINE void cells_range(sph_kernel_kind kernel, int continuity, int artificial, int diffusion,
                            int same_v, const cells_args *A, const cells_slot *S, PetscInt a,
                            const cells_slot *T, PetscInt first, PetscInt last, own_sums *o) {
  /* the buffer's fill and the pair count in locals: read through o they would be read
   * again after every store (the intrinsics' stores may alias anything) */
  int n_buf = o->n;
  PetscInt64 pairs = o->pairs;
  const __m512d xa = _mm512_set1_pd(S->X[a]), ya = _mm512_set1_pd(S->Y[a]);
  const __m512d vxa = _mm512_set1_pd(S->VX[a]), vya = _mm512_set1_pd(S->VY[a]);
  const int read_est = (artificial || continuity) && !same_v; /* else EX, EY may not exist */
  const __m512d exa = read_est ? _mm512_set1_pd(S->EX[a]) : _mm512_setzero_pd();
  const __m512d eya = read_est ? _mm512_set1_pd(S->EY[a]) : _mm512_setzero_pd();
  const __m512d Pa = _mm512_set1_pd(S->P[a]), Ja = _mm512_set1_pd(S->J[a]);
  const __m512d Ma = _mm512_set1_pd(S->M[a]);
  /* 1/rho exists only for the density diffusion (cells_copy_scalars) */
  const __m512d MIRa = diffusion ? _mm512_set1_pd(S->M[a] * S->IR[a]) : _mm512_setzero_pd();
  const __m512d RHOa = diffusion || artificial ? _mm512_set1_pd(S->RHO[a]) : _mm512_setzero_pd();
  const unsigned fa = S->FL[a];
  const __m512i no_pair = _mm512_set1_epi64(fa & FL_NO_PAIR);
  const __m512i wall_now = _mm512_set1_epi64(FL_WALL_NOW);
  const __m512d h2 = _mm512_set1_pd(A->h2), r2_floor = _mm512_set1_pd(A->r2_floor);
  const __m512d inv_h = _mm512_set1_pd(A->inv_h), one = _mm512_set1_pd(1.0);
  const __m512d grad_norm = _mm512_set1_pd(A->grad_norm);
  const __m512d grad_norm_inv_h = _mm512_set1_pd(A->grad_norm_inv_h);
  const __m512d sign = _mm512_set1_pd(-0.0);
  for (PetscInt b = first; b < last; b += 8) {
    const __mmask8 tail = last - b >= 8 ? 0xFF : (__mmask8)((1u << (last - b)) - 1u);
    const __m512d dx = _mm512_sub_pd(xa, _mm512_maskz_loadu_pd(tail, T->X + b));
    const __m512d dy = _mm512_sub_pd(ya, _mm512_maskz_loadu_pd(tail, T->Y + b));
    const __m512d r2 =
        _mm512_max_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), r2_floor);
    __mmask8 m = _mm512_mask_cmp_pd_mask(tail, r2, h2, _CMP_LT_OQ);
    if (!m)
      continue;
    const __m512i fb = _mm512_cvtepu8_epi64(_mm_maskz_loadu_epi8(tail, T->FL + b));
    if (fa & FL_NO_PAIR)
      m &= (__mmask8)~_mm512_test_epi64_mask(fb, no_pair);
    if ((fa & FL_SOLID) && A->excl) { /* the pair list's exclusions, lane by lane */
      unsigned both = m & _mm512_test_epi64_mask(fb, _mm512_set1_epi64(FL_SOLID));
      while (both) {
        const int l = __builtin_ctz(both);
        both &= both - 1;
        if (topology_excluded(A->excl, A->ps, S->order[a], T->order[b + l]))
          m &= (__mmask8) ~(1u << l);
      }
    }
    if (!m)
      continue;
    const __m512d r = _mm512_sqrt_pd(r2);
    /* sph_kernel_grad's g (1 - q)^k: (g - r g/h) (1 - r/h)^(k-1) */
    const __m512d mq = _mm512_fnmadd_pd(r, inv_h, one); /* 1 - q */
    __m512d grad = _mm512_mul_pd(_mm512_fnmadd_pd(r, grad_norm_inv_h, grad_norm), mq);
    if (kernel == SPH_KERNEL_WENDLAND)
      grad = _mm512_mul_pd(grad, mq);
    const __m512d Pb = _mm512_maskz_loadu_pd(m, T->P + b), Jb = _mm512_maskz_loadu_pd(m, T->J + b);
    const __m512d Mb = _mm512_maskz_loadu_pd(m, T->M + b);
    const __m512d press = _mm512_xor_pd(_mm512_add_pd(Pa, Pb), sign);
    const __m512d JJ = _mm512_mul_pd(Ja, Jb);
    const __m512d vvx = _mm512_sub_pd(vxa, _mm512_maskz_loadu_pd(m, T->VX + b));
    const __m512d vvy = _mm512_sub_pd(vya, _mm512_maskz_loadu_pd(m, T->VY + b));
    /* grad last (sph_force_iact.h): the brackets do not wait for the square root */
    __m512d T0 =
        _mm512_mul_pd(grad, _mm512_add_pd(_mm512_mul_pd(press, dx), _mm512_mul_pd(JJ, vvx)));
    __m512d T1 =
        _mm512_mul_pd(grad, _mm512_add_pd(_mm512_mul_pd(press, dy), _mm512_mul_pd(JJ, vvy)));
    __m512d vr = _mm512_setzero_pd(), RHOb = _mm512_setzero_pd();
    if (artificial || continuity) {
      /* same_v: no walls, v_est is v_visc (sph.c) */
      const __m512d vex = same_v ? vvx : _mm512_sub_pd(exa, _mm512_maskz_loadu_pd(m, T->EX + b));
      const __m512d vey = same_v ? vvy : _mm512_sub_pd(eya, _mm512_maskz_loadu_pd(m, T->EY + b));
      vr = _mm512_add_pd(_mm512_mul_pd(vex, dx), _mm512_mul_pd(vey, dy));
    }
    if (artificial || diffusion)
      RHOb = _mm512_maskz_loadu_pd(m, T->RHO + b);
    if (artificial) {
      const __mmask8 approaching = _mm512_mask_cmp_pd_mask(m, vr, _mm512_setzero_pd(), _CMP_LT_OQ);
      if (approaching) {
        const __m512d mu = _mm512_div_pd(_mm512_mul_pd(_mm512_set1_pd(A->h), vr),
                                         _mm512_add_pd(r2, _mm512_set1_pd(A->av_h2)));
        const __m512d num =
            _mm512_add_pd(_mm512_mul_pd(_mm512_set1_pd(A->neg_alpha_c0), mu),
                          _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(A->beta), mu), mu));
        const __m512d Pi =
            _mm512_div_pd(num, _mm512_mul_pd(_mm512_set1_pd(0.5), _mm512_add_pd(RHOa, RHOb)));
        const __m512d pgav = _mm512_mul_pd(Pi, grad);
        T0 = _mm512_mask_sub_pd(T0, approaching, T0, _mm512_mul_pd(pgav, dx));
        T1 = _mm512_mask_sub_pd(T1, approaching, T1, _mm512_mul_pd(pgav, dy));
      }
    }
    /* the partners' sums, in place, each with one rounding (fused multiply-adds: the pair
     * list's partner update, sph_force.c) */
    double *AX = T->AX + b, *AY = T->AY + b;
    _mm512_mask_storeu_pd(AX, m, _mm512_fnmadd_pd(Ma, T0, _mm512_maskz_loadu_pd(m, AX)));
    _mm512_mask_storeu_pd(AY, m, _mm512_fnmadd_pd(Ma, T1, _mm512_maskz_loadu_pd(m, AY)));
    /* a's own, buffered in partner order */
    _mm512_storeu_pd(o->x + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, T0)));
    _mm512_storeu_pd(o->y + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, T1)));
    if (continuity) {
      const __m512d q = _mm512_mul_pd(grad, vr);
      double *DR = T->DR + b;
      __m512d dr = _mm512_fmadd_pd(Ma, q, _mm512_maskz_loadu_pd(m, DR));
      _mm512_storeu_pd(o->q + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, q)));
      if (diffusion) {
        /* walls' densities are extrapolated (sph_wall.c): no diffusion through them */
        const __mmask8 md =
            fa & FL_WALL_NOW ? 0 : m & (__mmask8)~_mm512_test_epi64_mask(fb, wall_now);
        const __m512d D =
            _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(A->two_dhc), _mm512_sub_pd(RHOb, RHOa)),
                          _mm512_xor_pd(grad, sign));
        dr = _mm512_mask3_fnmadd_pd(MIRa, D, dr, md);
        /* a's diffusion term rides with its continuity term, compressed by m like
         * it so that the buffers stay aligned: 0 where md is off, and adding 0 leaves
         * a sum's bits as the pair-list sweep that skips the term */
        const __m512d IRb = _mm512_maskz_loadu_pd(m, T->IR + b);
        const __m512d own_d = _mm512_maskz_mul_pd(md, _mm512_mul_pd(Mb, IRb), D);
        _mm512_storeu_pd(o->d + n_buf, _mm512_maskz_compress_pd(m, own_d));
      }
      _mm512_mask_storeu_pd(DR, m, dr);
    }
    n_buf += __builtin_popcount((unsigned)m);
    pairs += __builtin_popcount((unsigned)m);
    if (n_buf > SPH_CELLS_BUF - 8) {
      o->n = n_buf;
      own_flush(o, continuity, diffusion);
      n_buf = 0;
    }
  }
  o->n = n_buf;
  o->pairs = pairs;
}
#endif
