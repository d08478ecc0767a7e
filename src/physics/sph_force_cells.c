/* The SPH momentum sweep over the cells of the last neighbour build, with
 * AVX-512: the same pairs, visited in the same order, with the same operations
 * per pair as the pair-list sweep (sph_force.c), so both give the same bits.
 *
 * Why it is faster: the pair list reaches both particles of every pair through
 * two indices (a gather per operand, a scatter per sum), one pair at a time. Here
 * every field the sweep reads is copied once per step into cell order
 * (sph_cells_work), and a particle's partners are contiguous runs of that copy:
 * its own cell after it plus the next cell (E), and the three cells above it
 * (NW, N, NE) — the half stencil of cells.c, whose cells are consecutive in
 * row-major order — each cut at the build to the rows within the cutoff in x
 * (cells.h, run_end1 ...). Eight candidates at a time are tested (r < h) and computed
 * with unit-stride loads; the partners' sums are updated in place with masked
 * stores. The particle's own sums are added in the order of its partners (the
 * lanes in use are compressed into a buffer and added one by one), which keeps
 * the order of every sum as in the pair list: bitwise the same results, on any
 * rank count (doc/parallel.md).
 *
 * Applies when the build has AVX-512 and the sweep is uncorrected, with the Lucy
 * or Wendland kernel (sph_force_cells_applies); otherwise sph_force.c's
 * pair-list sweep runs. */
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/events.h"
#include "dmhs/topology.h"
#include "sph_force_iact.h"
#include "sph_force.h"

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__)
#define SPH_CELLS_SIMD 1
#include <immintrin.h>
#else
#define SPH_CELLS_SIMD 0
#endif

#define SPH_CELLS_BUF 64 /* own-sum buffer, flushed before it can overflow */

/* flags of the copy: cells.c's 1 = ghost, 2 = wall, 4 = not liquid (at the build), and the
 * current type */
#define FL_NO_PAIR  3 /* two ghosts, two walls: no pair (cells.c) */
#define FL_SOLID    4 /* two bonded particles: maybe partners, left out (cells.c) */
#define FL_WALL_NOW 8 /* a wall now: no density diffusion through it */

PetscBool sph_force_cells_available(void) {
  return SPH_CELLS_SIMD ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool sph_force_cells_applies(const sph_params *sp) {
  if (!SPH_CELLS_SIMD || sp->sweep == SPH_SWEEP_PAIRS)
    return PETSC_FALSE;
  return !sp->kernel_correction && sp->kernel != SPH_KERNEL_CUBIC ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode sph_cells_work_destroy(sph_cells_work *w) {
  PetscFunctionBeginUser;
  for (int f = 0; f < SPH_CELLS_NFIELDS; f++)
    PetscCall(PetscFree(w->f[f]));
  PetscCall(PetscFree(w->fl));
  PetscCall(PetscMemzero(w, sizeof(*w)));
  PetscFunctionReturn(0);
}

#if SPH_CELLS_SIMD
/* The cell-order copy of the fields in `need` (bit f: w->f[f]), with 8 padding entries after
 * n so that a vector may read past the end; fields a run does not read are not allocated. */
static PetscErrorCode sph_cells_ensure(sph_cells_work *w, PetscInt n, unsigned need) {
  PetscFunctionBeginUser;
  if (n + 8 > w->n_alloc) {
    PetscCall(sph_cells_work_destroy(w));
    w->n_alloc = n + n / 16 + 8;
    PetscCall(PetscCalloc1(w->n_alloc, &w->fl));
  }
  for (int f = 0; f < SPH_CELLS_NFIELDS; f++)
    if ((need >> f & 1u) && !w->f[f])
      PetscCall(PetscCalloc1(w->n_alloc, &w->f[f]));
  PetscFunctionReturn(0);
}

typedef struct {
  const double *X, *Y, *VX, *VY, *EX, *EY, *P, *IR, *M, *RHO;
  double *AX, *AY, *DR;
  const unsigned char *FL;
  const PetscInt *order;       /* copy position -> row */
  const struct topology *excl; /* bonded pairs to leave out, or NULL */
  const particles *ps;
  double h2, r2_floor, inv_h, grad_norm, mu_sum, h, av_h2, neg_alpha_c0, beta, two_dhc;
} cells_args;

/* the particle a's own sums, in the order of its partners */
typedef struct {
  double x[SPH_CELLS_BUF + 8], y[SPH_CELLS_BUF + 8], q[SPH_CELLS_BUF + 8], d[SPH_CELLS_BUF + 8];
  int n;
  double ax, ay, ad;
  PetscInt64 pairs; /* pairs inside h: the flop count */
} own_sums;

SPH_INLINE void own_flush(own_sums *o, int continuity, int diffusion) {
  for (int t = 0; t < o->n; t++) {
    o->ax += o->x[t];
    o->ay += o->y[t];
    if (continuity) {
      o->ad += o->q[t];
      if (diffusion)
        o->ad += o->d[t];
    }
  }
  o->n = 0;
}

/* Particle a against the candidates [first, last) of the copy. */
SPH_INLINE void cells_range(sph_kernel_kind kernel, int continuity, int artificial, int diffusion,
                            int same_v, const cells_args *A, PetscInt a, PetscInt first,
                            PetscInt last, own_sums *o) {
  /* the buffer's fill and the pair count in locals: read through o they would be read
   * again after every store (the intrinsics' stores may alias anything) */
  int n_buf = o->n;
  PetscInt64 pairs = o->pairs;
  const __m512d xa = _mm512_set1_pd(A->X[a]), ya = _mm512_set1_pd(A->Y[a]);
  const __m512d vxa = _mm512_set1_pd(A->VX[a]), vya = _mm512_set1_pd(A->VY[a]);
  const int read_est = (artificial || continuity) && !same_v; /* else EX, EY may not exist */
  const __m512d exa = read_est ? _mm512_set1_pd(A->EX[a]) : _mm512_setzero_pd();
  const __m512d eya = read_est ? _mm512_set1_pd(A->EY[a]) : _mm512_setzero_pd();
  const __m512d Pa = _mm512_set1_pd(A->P[a]), IRa = _mm512_set1_pd(A->IR[a]);
  const __m512d Ma = _mm512_set1_pd(A->M[a]);
  const __m512d MIRa = _mm512_set1_pd(A->M[a] * A->IR[a]);
  const __m512d RHOa = diffusion || artificial ? _mm512_set1_pd(A->RHO[a]) : _mm512_setzero_pd();
  const unsigned fa = A->FL[a];
  const __m512i no_pair = _mm512_set1_epi64(fa & FL_NO_PAIR);
  const __m512i wall_now = _mm512_set1_epi64(FL_WALL_NOW);
  const __m512d h2 = _mm512_set1_pd(A->h2), r2_floor = _mm512_set1_pd(A->r2_floor);
  const __m512d inv_h = _mm512_set1_pd(A->inv_h), one = _mm512_set1_pd(1.0);
  const __m512d grad_norm = _mm512_set1_pd(A->grad_norm), mu_sum = _mm512_set1_pd(A->mu_sum);
  const __m512d sign = _mm512_set1_pd(-0.0);
  for (PetscInt b = first; b < last; b += 8) {
    const __mmask8 tail = last - b >= 8 ? 0xFF : (__mmask8)((1u << (last - b)) - 1u);
    const __m512d dx = _mm512_sub_pd(xa, _mm512_maskz_loadu_pd(tail, A->X + b));
    const __m512d dy = _mm512_sub_pd(ya, _mm512_maskz_loadu_pd(tail, A->Y + b));
    const __m512d r2 =
        _mm512_max_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), r2_floor);
    __mmask8 m = _mm512_mask_cmp_pd_mask(tail, r2, h2, _CMP_LT_OQ);
    if (!m)
      continue;
    const __m512i fb = _mm512_cvtepu8_epi64(_mm_maskz_loadu_epi8(tail, A->FL + b));
    if (fa & FL_NO_PAIR)
      m &= (__mmask8)~_mm512_test_epi64_mask(fb, no_pair);
    if ((fa & FL_SOLID) && A->excl) { /* the pair list's exclusions, lane by lane */
      unsigned both = m & _mm512_test_epi64_mask(fb, _mm512_set1_epi64(FL_SOLID));
      while (both) {
        const int l = __builtin_ctz(both);
        both &= both - 1;
        if (topology_excluded(A->excl, A->ps, A->order[a], A->order[b + l]))
          m &= (__mmask8) ~(1u << l);
      }
    }
    if (!m)
      continue;
    const __m512d r = _mm512_sqrt_pd(r2);
    const __m512d mq = _mm512_sub_pd(one, _mm512_mul_pd(r, inv_h)); /* 1 - q */
    __m512d grad = _mm512_mul_pd(_mm512_mul_pd(grad_norm, mq), mq);
    if (kernel == SPH_KERNEL_WENDLAND)
      grad = _mm512_mul_pd(grad, mq);
    const __m512d Pb = _mm512_maskz_loadu_pd(m, A->P + b),
                  IRb = _mm512_maskz_loadu_pd(m, A->IR + b);
    const __m512d Mb = _mm512_maskz_loadu_pd(m, A->M + b);
    const __m512d press = _mm512_xor_pd(_mm512_add_pd(Pa, Pb), sign);
    const __m512d visc = _mm512_mul_pd(_mm512_mul_pd(mu_sum, _mm512_mul_pd(IRa, IRb)), grad);
    const __m512d pg = _mm512_mul_pd(press, grad);
    const __m512d vvx = _mm512_sub_pd(vxa, _mm512_maskz_loadu_pd(m, A->VX + b));
    const __m512d vvy = _mm512_sub_pd(vya, _mm512_maskz_loadu_pd(m, A->VY + b));
    __m512d T0 = _mm512_add_pd(_mm512_mul_pd(pg, dx), _mm512_mul_pd(visc, vvx));
    __m512d T1 = _mm512_add_pd(_mm512_mul_pd(pg, dy), _mm512_mul_pd(visc, vvy));
    __m512d vr = _mm512_setzero_pd(), RHOb = _mm512_setzero_pd();
    if (artificial || continuity) {
      /* same_v: no walls, v_est is v_visc (sph.c) */
      const __m512d vex = same_v ? vvx : _mm512_sub_pd(exa, _mm512_maskz_loadu_pd(m, A->EX + b));
      const __m512d vey = same_v ? vvy : _mm512_sub_pd(eya, _mm512_maskz_loadu_pd(m, A->EY + b));
      vr = _mm512_add_pd(_mm512_mul_pd(vex, dx), _mm512_mul_pd(vey, dy));
    }
    if (artificial || diffusion)
      RHOb = _mm512_maskz_loadu_pd(m, A->RHO + b);
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
    /* the partners' sums, in place */
    double *AX = A->AX + b, *AY = A->AY + b;
    _mm512_mask_storeu_pd(AX, m,
                          _mm512_sub_pd(_mm512_maskz_loadu_pd(m, AX), _mm512_mul_pd(Ma, T0)));
    _mm512_mask_storeu_pd(AY, m,
                          _mm512_sub_pd(_mm512_maskz_loadu_pd(m, AY), _mm512_mul_pd(Ma, T1)));
    /* a's own, buffered in partner order */
    _mm512_storeu_pd(o->x + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, T0)));
    _mm512_storeu_pd(o->y + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, T1)));
    if (continuity) {
      const __m512d q = _mm512_mul_pd(grad, vr);
      double *DR = A->DR + b;
      __m512d dr = _mm512_add_pd(_mm512_maskz_loadu_pd(m, DR), _mm512_mul_pd(Ma, q));
      _mm512_storeu_pd(o->q + n_buf, _mm512_maskz_compress_pd(m, _mm512_mul_pd(Mb, q)));
      if (diffusion) {
        /* walls' densities are extrapolated (sph_wall.c): no diffusion through them */
        const __mmask8 md =
            fa & FL_WALL_NOW ? 0 : m & (__mmask8)~_mm512_test_epi64_mask(fb, wall_now);
        const __m512d D =
            _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(A->two_dhc), _mm512_sub_pd(RHOb, RHOa)),
                          _mm512_xor_pd(grad, sign));
        dr = _mm512_mask_sub_pd(dr, md, dr, _mm512_mul_pd(MIRa, D));
        /* a's diffusion term rides with its continuity term, compressed by m like
         * it so that the buffers stay aligned: 0 where md is off, and adding 0 leaves
         * a sum's bits as the pair-list sweep that skips the term */
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

SPH_INLINE PetscInt64 cells_sweep(sph_kernel_kind kernel, int continuity, int artificial,
                                  int diffusion, int same_v, const cells_args *A, const cells *c) {
  const PetscInt *restrict end1 = c->run_end1, *restrict first2 = c->run_first2,
                           *restrict last2 = c->run_last2;
  const PetscInt n = c->start[c->n[0] * c->n[1]];
  own_sums o;
  o.pairs = 0;
  for (PetscInt a = 0; a < n; a++) {
    o.n = 0;
    o.ax = A->AX[a];
    o.ay = A->AY[a];
    o.ad = continuity ? A->DR[a] : 0.0;
    cells_range(kernel, continuity, artificial, diffusion, same_v, A, a, a + 1, end1[a], &o);
    cells_range(kernel, continuity, artificial, diffusion, same_v, A, a, first2[a], last2[a], &o);
    own_flush(&o, continuity, diffusion);
    A->AX[a] = o.ax;
    A->AY[a] = o.ay;
    if (continuity)
      A->DR[a] = o.ad;
  }
  return o.pairs;
}

#define CSWEEP1(name, K, C, AV, D, V)                                                              \
  static PetscInt64 name(const cells_args *A, const cells *c) {                                    \
    return cells_sweep(K, C, AV, D, V, A, c);                                                      \
  }
/* each combination with v_est read apart from v_visc (walls) and as one (no walls) */
#define CSWEEP(name, K, C, AV, D) CSWEEP1(name, K, C, AV, D, 0) CSWEEP1(name##_v, K, C, AV, D, 1)
SPH_SWEEP_VARIANTS(CSWEEP, csweep_lucy, SPH_KERNEL_LUCY)
SPH_SWEEP_VARIANTS(CSWEEP, csweep_wendland, SPH_KERNEL_WENDLAND)

/* [Lucy, Wendland][summation, continuity, continuity + diffusion][artificial viscosity][same v] */
#define CPAIR(name)                                                                                \
  { name, name##_v }
static PetscInt64 (*const csweeps[2][3][2][2])(const cells_args *, const cells *) = {
    SPH_SWEEP_ROW(CPAIR, csweep_lucy),
    SPH_SWEEP_ROW(CPAIR, csweep_wendland),
};
#endif

PetscErrorCode sph_force_cells_compute(sim *s, const sph_params *sp, sph_cells_work *w,
                                       PetscBool visc_is_est) {
  particles *ps = &s->ps;
  const cells *c = &s->cel;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCheck(SPH_CELLS_SIMD, s->comm, PETSC_ERR_SUP,
             "-sph_force_sweep cells needs a build with AVX-512 (configure with "
             "-DDMHS_NATIVE=ON, the default, on a machine that has it)");
  PetscCheck(c->order, PETSC_COMM_SELF, PETSC_ERR_ORDER, "sph cells sweep before the first build");
  PetscCheck(c->start[c->n[0] * c->n[1]] == n, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "sph cells sweep: %" PetscInt_FMT " rows, the last build sorted %" PetscInt_FMT, n,
             c->start[c->n[0] * c->n[1]]);
#if SPH_CELLS_SIMD
  const int continuity = sp->density == SPH_DENSITY_CONTINUITY;
  const int artificial = sp->av_alpha > 0.0 || sp->av_beta > 0.0;
  const int diffusion = continuity && sp->delta > 0;
  const int need_est = (continuity || artificial) && !visc_is_est;
  unsigned need = 0x1 | 0x2 | 0x4 | 0x8 | 0x40 | 0x80 | 0x100 | 0x400 | 0x800; /* always */
  if (need_est)
    need |= 0x10 | 0x20;
  if (artificial || diffusion)
    need |= 0x200;
  if (continuity)
    need |= 0x1000;
  PetscCall(sph_cells_ensure(w, n, need));
  double *X = w->f[0], *Y = w->f[1], *VX = w->f[2], *VY = w->f[3];
  double *EX = visc_is_est ? VX : w->f[4], *EY = visc_is_est ? VY : w->f[5];
  double *P = w->f[6], *IR = w->f[7], *M = w->f[8], *RHO = w->f[9];
  double *AX = w->f[10], *AY = w->f[11], *DR = w->f[12];
  const PetscInt *restrict order = c->order;
  /* one stream per loop: the rows are in cell order already (cells_sort.c), so each
   * loop reads nearly in order */
  for (PetscInt k = 0; k < n; k++)
    M[k] = ps->mass[order[k]];
  for (PetscInt k = 0; k < n; k++) {
    const PetscInt i = order[k];
    X[k] = ps->x[i][0];
    Y[k] = ps->x[i][1];
  }
  const double(*vv)[2] = sph_viscous_velocity(ps, visc_is_est);
  for (PetscInt k = 0; k < n; k++) {
    const PetscInt i = order[k];
    VX[k] = vv[i][0];
    VY[k] = vv[i][1];
  }
  if (need_est)
    for (PetscInt k = 0; k < n; k++) {
      const PetscInt i = order[k];
      EX[k] = ps->v_est[i][0];
      EY[k] = ps->v_est[i][1];
    }
  for (PetscInt k = 0; k < n; k++) {
    const PetscInt i = order[k];
    IR[k] = ps->rho[i];
    P[k] = ps->p[i];
  }
  if (artificial || diffusion)
    PetscCall(PetscArraycpy(RHO, IR, n));
  for (PetscInt k = 0; k < n; k++) { /* vectorised: the divisions eight at a time */
    IR[k] = 1.0 / IR[k];
    P[k] = P[k] * IR[k] * IR[k];
  }
  for (PetscInt k = 0; k < n; k++) {
    const PetscInt i = order[k];
    AX[k] = ps->a[i][0];
    AY[k] = ps->a[i][1];
  }
  if (continuity)
    for (PetscInt k = 0; k < n; k++)
      DR[k] = ps->drho[order[k]];
  for (PetscInt k = 0; k < n; k++)
    w->fl[k] = (unsigned char)((c->flag[k] & (FL_NO_PAIR | FL_SOLID)) |
                               (ps->type[order[k]] == PTYPE_WALL ? FL_WALL_NOW : 0));
  const double norm = sph_kernel_norm(sp->kernel, 2, sp->h), inv_h = 1.0 / sp->h;
  const cells_args A = {
      .X = X,
      .Y = Y,
      .VX = VX,
      .VY = VY,
      .EX = EX,
      .EY = EY,
      .P = P,
      .IR = IR,
      .M = M,
      .RHO = RHO,
      .AX = AX,
      .AY = AY,
      .DR = DR,
      .FL = w->fl,
      .order = order,
      .excl = c->excl,
      .ps = ps,
      .h2 = sp->h * sp->h,
      .r2_floor = SPH_R2_FLOOR * (sp->h * sp->h),
      .inv_h = inv_h,
      .grad_norm = sph_kernel_grad_norm(sp->kernel, 2, norm, inv_h),
      .mu_sum = 2.0 * sp->rho0 * sp->nu,
      .h = sp->h,
      .av_h2 = 0.01 * sp->h * sp->h,
      .neg_alpha_c0 = -sp->av_alpha * sp->c0,
      .beta = sp->av_beta,
      .two_dhc = 2.0 * (sp->delta * 0.5 * sp->h * sp->c0),
  };
  const int density = continuity ? (diffusion ? 2 : 1) : 0;
  w->n_pairs =
      csweeps[sp->kernel == SPH_KERNEL_WENDLAND][density][artificial][visc_is_est ? 1 : 0](&A, c);
  for (PetscInt k = 0; k < n; k++) {
    const PetscInt i = order[k];
    ps->a[i][0] = AX[k];
    ps->a[i][1] = AY[k];
    if (continuity)
      ps->drho[i] = DR[k];
  }
#else
  (void)w;
  (void)visc_is_est;
  (void)sp;
#endif
  PetscFunctionReturn(0);
}
