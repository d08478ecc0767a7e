/* The SPH momentum sweep over the cells of the last neighbour build, with
 * AVX-512 or AVX2: the same pairs, visited in the same order, with the same operations
 * per pair as the pair-list sweep (sph_force.c), so both give the same bits.
 *
 * Why it is faster: the pair list reaches both particles of every pair through
 * two indices (a gather per operand, a scatter per sum), one pair at a time. Here
 * every field the sweep reads is copied into cell order, and a particle's partners
 * are contiguous runs of that copy: its own cell after it plus the next cell (E), and
 * the three cells above it (NW, N, NE) — the half stencil of cells.c, whose cells are
 * consecutive in row-major order — each cut at the build to the rows within the
 * cutoff in x (cells.h, run_end1 ...). The first run lies in the particle's row of
 * cells, the second in the row above, so the copy holds two rows of cells at a time
 * (sph_cells_work's two slots, used in turn): a row is copied in just before it is
 * needed and its sums go back to the particles right after its sweep, while they are
 * still in the core's cache. A copy of every row at once streamed the whole field set
 * through memory three times a step (copy, sweep, write-back) and took an eighth of
 * the step. Eight candidates (AVX-512) or four (AVX2) at a time are tested (r < h)
 * and computed with unit-stride loads; the partners' sums are updated in place with masked
 * stores. The particle's own sums are added in the order of its partners (the
 * lanes in use are compressed into a buffer and added one by one), which keeps
 * the order of every sum as in the pair list: bitwise the same results, on any
 * rank count (doc/parallel.md). The partners' sums take each term in one fused
 * multiply-add, and so does the pair list's update of the row that comes second in
 * the cell order (sph_force.c).
 *
 * Applies when the build has AVX-512 or AVX2 with FMA and the sweep is uncorrected, with the Lucy
 * or Wendland kernel (sph_force_cells_applies); otherwise sph_force.c's
 * pair-list sweep runs. */
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/events.h"
#include "dmhs/topology.h"
#include "sph_force_iact.h"
#include "sph_force.h"

#include "sph_force_cells_range.h"

/* the range kernel of the widest vectors the build has: SPH_CELLS_SIMD lanes */
#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__)
#define SPH_CELLS_SIMD 8
#include "sph_force_cells_avx512.h"
#elif defined(__AVX2__) && defined(__FMA__)
#define SPH_CELLS_SIMD 4
#include "sph_force_cells_avx2.h"
#else
#define SPH_CELLS_SIMD 0
#endif

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
  for (int k = 0; k < 2; k++) {
    for (int f = 0; f < SPH_CELLS_NFIELDS; f++)
      PetscCall(PetscFree(w->f[k][f]));
    PetscCall(PetscFree(w->fl[k]));
  }
  PetscCall(PetscMemzero(w, sizeof(*w)));
  PetscFunctionReturn(0);
}

#if SPH_CELLS_SIMD
/* Two slots of n_row rows each (and SPH_CELLS_PAD more) for the fields in `need` (bit f:
 * w->f[k][f]); fields a run does not read are not allocated. */
static PetscErrorCode sph_cells_ensure(sph_cells_work *w, PetscInt n_row, unsigned need) {
  PetscFunctionBeginUser;
  if (n_row > w->n_alloc) {
    const PetscInt grown = n_row + n_row / 4;
    PetscCall(sph_cells_work_destroy(w));
    w->n_alloc = grown;
  }
  for (int k = 0; k < 2; k++) {
    if (!w->fl[k])
      PetscCall(PetscCalloc1(w->n_alloc + SPH_CELLS_PAD, &w->fl[k]));
    for (int f = 0; f < SPH_CELLS_NFIELDS; f++)
      if ((need >> f & 1u) && !w->f[k][f])
        PetscCall(PetscCalloc1(w->n_alloc + SPH_CELLS_PAD, &w->f[k][f]));
  }
  PetscFunctionReturn(0);
}

/* A two-component field's rows into two arrays, and back (unit stride: vectorised) */
SPH_INLINE void cells_copy_pair(double *restrict d0, double *restrict d1,
                                const double *restrict src, PetscInt len) {
  for (PetscInt t = 0; t < len; t++) {
    d0[t] = src[2 * t];
    d1[t] = src[2 * t + 1];
  }
}
SPH_INLINE void cells_store_pair(double *restrict dst, const double *restrict s0,
                                 const double *restrict s1, PetscInt len) {
  for (PetscInt t = 0; t < len; t++) {
    dst[2 * t] = s0[t];
    dst[2 * t + 1] = s1[t];
  }
}

/* m, p/rho^2, J = sqrt(mu_i + mu_j)/rho (sph_force_iact.h) and, with keep_ir (a constant: the
 * density diffusion reads it), 1/rho; vectorised, the divisions eight at a time */
SPH_INLINE void cells_copy_scalars(double *restrict M, double *restrict IR, double *restrict P,
                                   double *restrict J, const double *restrict mass,
                                   const double *restrict rho, const double *restrict p,
                                   double sqrt_mu_sum, PetscInt len, int keep_ir) {
  for (PetscInt t = 0; t < len; t++) {
    const double ir = 1.0 / rho[t];
    M[t] = mass[t];
    if (keep_ir)
      IR[t] = ir;
    P[t] = p[t] * ir * ir;
    J[t] = sqrt_mu_sum * ir;
  }
}
/* the pair flags of the build (cells.c) and whether a row is a wall now */
SPH_INLINE void cells_copy_flags(unsigned char *restrict fl, const unsigned char *restrict flag,
                                 const PetscInt *restrict type, PetscInt len) {
  for (PetscInt t = 0; t < len; t++)
    fl[t] = (unsigned char)((flag[t] & (FL_NO_PAIR | FL_SOLID)) |
                            (type[t] == PTYPE_WALL ? FL_WALL_NOW : 0));
}

/* The particles of one row of cells, cell-order positions [first, last), held in slot S; their
 * upper partners are in slot T, which holds the row above (from position last on). */
SPH_INLINE PetscInt64 cells_sweep(sph_kernel_kind kernel, int continuity, int artificial,
                                  int diffusion, int same_v, const cells_args *A, const cells *c,
                                  const cells_slot *S, const cells_slot *T, PetscInt first,
                                  PetscInt last) {
  const PetscInt base_s = first, base_t = last;
  const PetscInt *restrict end1 = c->run_end1, *restrict first2 = c->run_first2,
                           *restrict last2 = c->run_last2;
  own_sums o;
  o.pairs = 0;
  for (PetscInt a = first; a < last; a++) {
    const PetscInt t = a - base_s;
    o.n = 0;
    o.ax = S->AX[t];
    o.ay = S->AY[t];
    o.ad = continuity ? S->DR[t] : 0.0;
    cells_range(kernel, continuity, artificial, diffusion, same_v, A, S, t, S, t + 1,
                end1[a] - base_s, &o);
    if (last2[a] > first2[a])
      cells_range(kernel, continuity, artificial, diffusion, same_v, A, S, t, T, first2[a] - base_t,
                  last2[a] - base_t, &o);
    own_flush(&o, continuity, diffusion);
    S->AX[t] = o.ax;
    S->AY[t] = o.ay;
    if (continuity)
      S->DR[t] = o.ad;
  }
  return o.pairs;
}

#define CSWEEP1(name, K, C, AV, D, V)                                                              \
  static PetscInt64 name(const cells_args *A, const cells *c, const cells_slot *S,                 \
                         const cells_slot *T, PetscInt first, PetscInt last) {                     \
    return cells_sweep(K, C, AV, D, V, A, c, S, T, first, last);                                   \
  }
/* each combination with v_est read apart from v_visc (walls) and as one (no walls) */
#define CSWEEP(name, K, C, AV, D) CSWEEP1(name, K, C, AV, D, 0) CSWEEP1(name##_v, K, C, AV, D, 1)
SPH_SWEEP_VARIANTS(CSWEEP, csweep_lucy, SPH_KERNEL_LUCY)
SPH_SWEEP_VARIANTS(CSWEEP, csweep_wendland, SPH_KERNEL_WENDLAND)

/* [Lucy, Wendland][summation, continuity, continuity + diffusion][artificial viscosity][same v] */
#define CPAIR(name)                                                                                \
  { name, name##_v }
static PetscInt64 (*const csweeps[2][3][2][2])(const cells_args *, const cells *,
                                               const cells_slot *, const cells_slot *, PetscInt,
                                               PetscInt) = {
    SPH_SWEEP_ROW(CPAIR, csweep_lucy),
    SPH_SWEEP_ROW(CPAIR, csweep_wendland),
};
#endif

#if SPH_CELLS_SIMD
typedef struct {
  const cells *c;
  particles *ps;
  const double (*vv)[2]; /* the viscous term's velocity (sph_viscous_velocity) */
  int need_est, continuity, copy_rho, keep_ir;
  double sqrt_mu_sum; /* J = sqrt(mu_i + mu_j)/rho (sph_force_iact.h) */
  int zero_sums;      /* a and drho hold nothing yet (sim's rates_unset): the sums start at 0 */
} cells_fill_args;

/* The next segment (cells.h) that reaches past `first`, from *seg on: the copies visit the
 * rows of cells in order, so each keeps its own cursor. */
static inline PetscInt cells_segment_from(const cells *c, PetscInt first, PetscInt *seg) {
  while (*seg < c->n_seg && c->seg_pos[*seg + 1] <= first)
    (*seg)++;
  return *seg;
}

/* Cell-order positions [first, last) into slot S (slot position = position - first). */
static void cells_slot_fill(const cells_fill_args *F, cells_slot *S, PetscInt first, PetscInt last,
                            PetscInt *seg) {
  const cells *c = F->c;
  const particles *ps = F->ps;
  S->order = c->order + first;
  if (F->zero_sums) {
    memset(S->AX, 0, (size_t)(last - first) * sizeof(double));
    memset(S->AY, 0, (size_t)(last - first) * sizeof(double));
    if (F->continuity)
      memset(S->DR, 0, (size_t)(last - first) * sizeof(double));
  }
  for (PetscInt g = cells_segment_from(c, first, seg); g < c->n_seg && c->seg_pos[g] < last; g++) {
    const PetscInt k0 = PetscMax(c->seg_pos[g], first), k1 = PetscMin(c->seg_pos[g + 1], last);
    const PetscInt i0 = c->seg_row[g] + (k0 - c->seg_pos[g]), t0 = k0 - first, len = k1 - k0;
    cells_copy_pair(S->X + t0, S->Y + t0, ps->x[i0], len);
    cells_copy_pair(S->VX + t0, S->VY + t0, F->vv[i0], len);
    if (F->need_est)
      cells_copy_pair(S->EX + t0, S->EY + t0, ps->v_est[i0], len);
    if (!F->zero_sums)
      cells_copy_pair(S->AX + t0, S->AY + t0, ps->a[i0], len);
    if (F->keep_ir)
      cells_copy_scalars(S->M + t0, S->IR + t0, S->P + t0, S->J + t0, ps->mass + i0, ps->rho + i0,
                         ps->p + i0, F->sqrt_mu_sum, len, 1);
    else
      cells_copy_scalars(S->M + t0, NULL, S->P + t0, S->J + t0, ps->mass + i0, ps->rho + i0,
                         ps->p + i0, F->sqrt_mu_sum, len, 0);
    if (F->copy_rho)
      memcpy(S->RHO + t0, ps->rho + i0, (size_t)len * sizeof(double));
    if (F->continuity && !F->zero_sums)
      memcpy(S->DR + t0, ps->drho + i0, (size_t)len * sizeof(double));
    cells_copy_flags(S->FL + t0, c->flag + k0, ps->type + i0, len);
  }
}

/* The sums of positions [first, last) from slot S back to their rows: the owned rows only,
 * the ghosts' sums are dropped (no reverse communication, doc/parallel.md). */
static void cells_slot_store(const cells_fill_args *F, const cells_slot *S, PetscInt first,
                             PetscInt last, PetscInt *seg) {
  const cells *c = F->c;
  particles *ps = F->ps;
  for (PetscInt g = cells_segment_from(c, first, seg); g < c->n_seg && c->seg_pos[g] < last; g++) {
    if (c->seg_row[g] >= ps->n_owned)
      continue;
    const PetscInt k0 = PetscMax(c->seg_pos[g], first), k1 = PetscMin(c->seg_pos[g + 1], last);
    const PetscInt i0 = c->seg_row[g] + (k0 - c->seg_pos[g]), t0 = k0 - first, len = k1 - k0;
    cells_store_pair(ps->a[i0], S->AX + t0, S->AY + t0, len);
    if (F->continuity)
      memcpy(ps->drho + i0, S->DR + t0, (size_t)len * sizeof(double));
  }
}
#endif

PetscErrorCode sph_force_cells_compute(sim *s, const sph_params *sp, sph_cells_work *w,
                                       PetscBool visc_is_est) {
  particles *ps = &s->ps;
  const cells *c = &s->cel;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCheck(SPH_CELLS_SIMD, s->comm, PETSC_ERR_SUP,
             "-sph_force_sweep cells needs a build with AVX-512 or AVX2 (configure "
             "with -DDMHS_NATIVE=ON, the default, on a machine that has it)");
  PetscCheck(c->order, PETSC_COMM_SELF, PETSC_ERR_ORDER, "sph cells sweep before the first build");
  PetscCheck(c->start[c->n[0] * c->n[1]] == n, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "sph cells sweep: %" PetscInt_FMT " rows, the last build sorted %" PetscInt_FMT, n,
             c->start[c->n[0] * c->n[1]]);
#if SPH_CELLS_SIMD
  const int continuity = sp->density == SPH_DENSITY_CONTINUITY;
  const int artificial = sp->av_alpha > 0.0 || sp->av_beta > 0.0;
  const int diffusion = continuity && sp->delta > 0;
  const int need_est = (continuity || artificial) && !visc_is_est;
  unsigned need = 0x1 | 0x2 | 0x4 | 0x8 | 0x40 | 0x100 | 0x400 | 0x800 | 0x2000; /* always */
  if (need_est)
    need |= 0x10 | 0x20;
  if (artificial || diffusion)
    need |= 0x200;
  if (diffusion)
    need |= 0x80; /* 1/rho */
  if (continuity)
    need |= 0x1000;
  const PetscInt n0 = c->n[0], n1 = c->n[1];
  PetscInt n_row = 1;
  for (PetscInt cy = 0; cy < n1; cy++)
    n_row = PetscMax(n_row, c->start[(cy + 1) * n0] - c->start[cy * n0]);
  PetscCall(sph_cells_ensure(w, n_row, need));
  cells_slot slot[2];
  for (int k = 0; k < 2; k++) {
    double *const *f = w->f[k];
    slot[k] = (cells_slot){
        .X = f[0],
        .Y = f[1],
        .VX = f[2],
        .VY = f[3],
        .EX = visc_is_est ? f[2] : f[4],
        .EY = visc_is_est ? f[3] : f[5],
        .P = f[6],
        .IR = f[7],
        .M = f[8],
        .RHO = f[9],
        .AX = f[10],
        .AY = f[11],
        .DR = f[12],
        .J = f[13],
        .FL = w->fl[k],
    };
  }
  const double norm = sph_kernel_norm(sp->kernel, 2, sp->h), inv_h = 1.0 / sp->h;
  const cells_args A = {
      .excl = c->excl,
      .ps = ps,
      .h2 = sp->h * sp->h,
      .r2_floor = SPH_R2_FLOOR * (sp->h * sp->h),
      .inv_h = inv_h,
      .grad_norm = sph_kernel_grad_norm(sp->kernel, 2, norm, inv_h),
      .grad_norm_inv_h = sph_kernel_grad_norm(sp->kernel, 2, norm, inv_h) * inv_h,
      .h = sp->h,
      .av_h2 = 0.01 * sp->h * sp->h,
      .neg_alpha_c0 = -sp->av_alpha * sp->c0,
      .beta = sp->av_beta,
      .two_dhc = 2.0 * (sp->delta * 0.5 * sp->h * sp->c0),
  };
  const int density = continuity ? (diffusion ? 2 : 1) : 0;
  PetscInt64 (*const sweep)(const cells_args *, const cells *, const cells_slot *,
                            const cells_slot *, PetscInt, PetscInt) =
      csweeps[sp->kernel == SPH_KERNEL_WENDLAND][density][artificial][visc_is_est ? 1 : 0];
  const cells_fill_args F = {
      .c = c,
      .ps = ps,
      .vv = sph_viscous_velocity(ps, visc_is_est),
      .need_est = need_est,
      .continuity = continuity,
      .copy_rho = artificial || diffusion,
      .keep_ir = diffusion,
      .sqrt_mu_sum = sqrt(2.0 * sp->rho0 * sp->nu), /* one liquid: mu = rho0 nu */
      .zero_sums = s->rates_unset,
  };
  s->rates_unset = PETSC_FALSE; /* set now, for every owned row (cells_slot_store) */
  /* row cy in slot cy % 2: filled two rows ahead, swept with the row above as partners,
   * written back, then refilled with row cy + 2 */
  PetscInt fill_seg = 0, back_seg = 0;
  cells_slot_fill(&F, &slot[0], c->start[0], c->start[n0], &fill_seg);
  if (n1 > 1)
    cells_slot_fill(&F, &slot[1], c->start[n0], c->start[2 * n0], &fill_seg);
  w->n_pairs = 0;
  for (PetscInt cy = 0; cy < n1; cy++) {
    cells_slot *S = &slot[cy % 2];
    const PetscInt first = c->start[cy * n0], last = c->start[(cy + 1) * n0];
    w->n_pairs += sweep(&A, c, S, &slot[(cy + 1) % 2], first, last);
    cells_slot_store(&F, S, first, last, &back_seg);
    if (cy + 2 < n1)
      cells_slot_fill(&F, S, c->start[(cy + 2) * n0], c->start[(cy + 3) * n0], &fill_seg);
  }
#else
  (void)w;
  (void)visc_is_est;
  (void)sp;
#endif
  PetscFunctionReturn(0);
}
