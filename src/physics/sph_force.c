/* The SPH momentum sweep (pressure + Morris viscosity [+ Monaghan artificial
 * viscosity]); with continuity density it also accumulates d rho/dt in the
 * same pass over pairs, as LAMMPS' sph/taitwater does: one pair loop instead
 * of two. Pair arithmetic: sph_force_iact.h, and sph_correction_iact.h for the
 * corrected pressure and viscous terms (-sph_kernel_correction). The run-time
 * choices (kernel, continuity [+ density diffusion], artificial viscosity,
 * correction) select one of 36 specialised sweeps before the loop. */
#include "dmhs/sim.h"
#include "dmhs/events.h"
#include "sph_force_iact.h"
#include "sph_force.h"

typedef struct {
  PetscInt n_pairs;
  const PetscInt *restrict pi, *restrict pj;
  const PetscInt *restrict position; /* per row, its place in the cell order (cells.h) */
  const double (*restrict x)[2], (*restrict v_est)[2], (*restrict v_visc)[2];
  const double *restrict mass, *restrict rho;
  const double *restrict P, *restrict inv_rho; /* p/rho^2 and 1/rho per particle */
  const double *restrict J;                    /* sqrt(mu_i + mu_j)/rho per particle */
  const double *restrict p;                    /* pressure (corrected sweeps) */
  double (*restrict a)[2];
  double *restrict drho;
  const PetscInt *restrict type;
  const sph_correction *restrict corr; /* per-row tensors (corrected sweeps only) */
  const double (*restrict pair)[2];    /* per-pair F, 1/r^2 of the correction pass */
  double h, inv_h, norm, alpha, beta, c0, delta_hs_c0;
  double nu2; /* 2 nu (corrected sweeps) */
} force_args;

/* Floating-point operations of one pair inside h as sph_force_iact.h writes them (a square
 * root counted as one), both particles' sums included: -log_view's flop rates. */
double sph_force_flops_per_pair(int continuity, int artificial, int diffusion, int corrected) {
  double f = corrected ? 40.0 : 33.0; /* r^2, sqrt, kernel gradient, pressure and viscous T */
  if (continuity)
    f += 7.0; /* (v_i - v_j) . r, both densities' rates */
  if (diffusion)
    f += 9.0;
  if (artificial)
    f += 13.0; /* charged to every pair, approaching or not */
  return f;
}

SPH_INLINE PetscInt64 force_sweep(sph_kernel_kind kernel, int continuity, int artificial,
                                  int diffusion, int corrected, const force_args *A) {
  PetscInt64 inside = 0; /* pairs inside h: the flop count */
  const PetscInt *restrict pi = A->pi, *restrict pj = A->pj;
  const double(*restrict x)[2] = A->x, (*restrict v_est)[2] = A->v_est,
                         (*restrict v_visc)[2] = A->v_visc;
  const double *restrict mass = A->mass, *restrict rho = A->rho;
  const double *restrict P = A->P, *restrict inv_rho = A->inv_rho;
  double(*restrict a)[2] = A->a;
  double *restrict drho = A->drho;
  const double *restrict J = A->J;
  const double h = A->h, inv_h = A->inv_h, norm = A->norm, h2 = h * h;
  const double grad_norm = sph_kernel_grad_norm(kernel, 2, norm, inv_h);
  /* the correction pass left F and 1/r^2 of every pair: the artificial
   * viscosity and the density diffusion, which need r and dW/dr, recompute */
  const int cached = corrected && !artificial && !diffusion;
  for (PetscInt k = 0; k < A->n_pairs; k++) {
    const PetscInt i = pi[k], j = pj[k];
    const double rij[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    double r2 = 0.0, grad = 0.0, F = 0.0, inv_r2 = 0.0;
    if (cached) {
      inv_r2 = A->pair[k][1];
      if (inv_r2 == 0.0)
        continue; /* beyond h */
      F = A->pair[k][0];
    } else {
      r2 = PetscMax(rij[0] * rij[0] + rij[1] * rij[1], SPH_R2_FLOOR * h2);
      if (r2 >= h2)
        continue; /* listed within the skin, not (yet) interacting */
      const double r = sqrt(r2);
      if (corrected) { /* F as the correction pass computed it */
        double w, dwdr;
        sph_kernel_eval(kernel, 2, norm, inv_h, r, &w, &dwdr);
        inv_r2 = 1.0 / r2;
        F = dwdr * (r * inv_r2);
        grad = F;
      } else {
        grad = sph_kernel_grad(kernel, 2, grad_norm, norm, inv_h, r);
      }
    }
    inside++;
    /* Each pair's sums as the cells sweep (sph_force_cells.c) adds them: the row that comes
     * first in the cell order adds m T to its own sums, the other has m T subtracted in one
     * fused multiply-add (a single rounding: the vectorised sweep's partner update, one
     * instruction instead of two). The two round differently, so which row is which follows
     * the cell order, which is the same on every rank count (cells.h), and not the pair
     * list's i < j of local rows, which is not. Corrected sweeps keep both sides unfused.
     * f and s: the first and the second row; sgn turns the pair's terms, seen from i, into
     * the same terms seen from f (an exact sign flip). */
    const int i_first = A->position[i] < A->position[j];
    const PetscInt f = i_first ? i : j, s = i_first ? j : i;
    const double sgn = i_first ? 1.0 : -1.0;
    const double vvisc[2] = {v_visc[i][0] - v_visc[j][0], v_visc[i][1] - v_visc[j][1]};
    double T[2] = {0.0, 0.0}; /* antisymmetric: a_i += m_j T, a_j -= m_i T */
    if (corrected) {
      /* each side with its own tensors; the j side is the i side of the reversed pair, bit for bit
       */
      const double rji[2] = {-rij[0], -rij[1]}, vji[2] = {-vvisc[0], -vvisc[1]};
      const double dp = A->p[j] - A->p[i], inv_rho2 = inv_rho[i] * inv_rho[j];
      double Ti[2], Tj[2];
      sph_corrected_iact(rij, F, inv_r2, dp, inv_rho2, vvisc, A->nu2 * inv_rho[j], &A->corr[i], Ti);
      sph_corrected_iact(rji, F, inv_r2, -dp, inv_rho2, vji, A->nu2 * inv_rho[i], &A->corr[j], Tj);
      a[i][0] += mass[j] * Ti[0];
      a[i][1] += mass[j] * Ti[1];
      a[j][0] += mass[i] * Tj[0];
      a[j][1] += mass[i] * Tj[1];
    } else {
      sph_force_iact(rij, grad, P[i], P[j], J[i], J[j], vvisc, T);
    }
    if (artificial || continuity) {
      const double vij[2] = {v_est[i][0] - v_est[j][0], v_est[i][1] - v_est[j][1]};
      if (artificial)
        sph_force_iact_artificial_viscosity(rij, r2, grad, rho[i], rho[j], vij, A->alpha, A->beta,
                                            A->c0, h, T);
      if (continuity) {
        if (!corrected) { /* else -rho_i div_i per particle (sph_force_compute) */
          const double q = sph_continuity_iact(rij, grad, vij);
          drho[f] += mass[s] * q; /* q is symmetric in the pair */
          drho[s] = fma(mass[f], q, drho[s]);
        }
        /* walls' densities are extrapolated (sph_wall.c): no diffusion through them */
        if (diffusion && A->type[i] != PTYPE_WALL && A->type[j] != PTYPE_WALL) {
          const double D = sph_density_diffusion_iact(grad, rho[i], rho[j], A->delta_hs_c0);
          if (corrected) {
            drho[i] += mass[j] * inv_rho[j] * D;
            drho[j] -= mass[i] * inv_rho[i] * D;
          } else {
            const double D_f = sgn * D;
            drho[f] += mass[s] * inv_rho[s] * D_f;
            drho[s] = fma(-(mass[f] * inv_rho[f]), D_f, drho[s]);
          }
        }
      }
    }
    /* ghost rows receive contributions too; they are discarded (Newton's third
     * law inside a rank only), which keeps the loop free of tests of ownership */
    if (corrected && artificial) { /* T holds the antisymmetric terms */
      a[i][0] += mass[j] * T[0];
      a[i][1] += mass[j] * T[1];
      a[j][0] -= mass[i] * T[0];
      a[j][1] -= mass[i] * T[1];
    } else if (!corrected) {
      for (int k = 0; k < 2; k++) {
        const double T_f = sgn * T[k];
        a[f][k] += mass[s] * T_f;
        a[s][k] = fma(-mass[f], T_f, a[s][k]);
      }
    }
  }
  return inside;
}

#define SWEEP1(name, K, C, AV, D, KGC)                                                             \
  static PetscInt64 name(const force_args *A) {                                                    \
    return force_sweep(K, C, AV, D, KGC, A);                                                       \
  }
/* each combination plain and corrected (-sph_kernel_correction) */
#define SWEEP(name, K, C, AV, D) SWEEP1(name, K, C, AV, D, 0) SWEEP1(name##_kgc, K, C, AV, D, 1)
SPH_SWEEP_VARIANTS(SWEEP, sweep_lucy, SPH_KERNEL_LUCY)
SPH_SWEEP_VARIANTS(SWEEP, sweep_cubic, SPH_KERNEL_CUBIC)
SPH_SWEEP_VARIANTS(SWEEP, sweep_wendland, SPH_KERNEL_WENDLAND)

/* [kernel][density: summation, continuity, continuity + diffusion][artificial viscosity][corrected]
 */
#define PAIR(name)                                                                                 \
  { name, name##_kgc }
static PetscInt64 (*const sweeps[3][3][2][2])(const force_args *) = {
    SPH_SWEEP_ROW(PAIR, sweep_lucy),
    SPH_SWEEP_ROW(PAIR, sweep_cubic),
    SPH_SWEEP_ROW(PAIR, sweep_wendland),
};

PetscErrorCode sph_force_compute(sim *s, const sph_params *sp, sph_force_work *work,
                                 const sph_correction *corr, const double (*pair)[2]) {
  particles *ps = &s->ps;
  const int continuity = sp->density == SPH_DENSITY_CONTINUITY;
  const int artificial = sp->av_alpha > 0.0 || sp->av_beta > 0.0;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_force, 0, 0, 0, 0));
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscCheck(sp->sweep != SPH_SWEEP_CELLS || (!corr && sph_force_cells_applies(sp)), s->comm,
             PETSC_ERR_ARG_INCOMP, "-sph_force_sweep cells: %s",
             !sph_force_cells_available()
                 ? "this build has neither AVX-512 nor AVX2 (configure with -DDMHS_NATIVE=ON on a "
                   "machine that has one)"
                 : "it needs no kernel correction and the Lucy or Wendland kernel; use "
                   "-sph_force_sweep auto or pairs");
  if (!corr && sph_force_cells_applies(sp)) {
    if (!work->cells)
      PetscCall(PetscNew(&work->cells));
    PetscCall(sph_force_cells_compute(s, sp, work->cells, work->visc_is_est));
    PetscCall(PetscLogFlops(sph_force_flops_per_pair(continuity, artificial, sp->delta > 0, 0) *
                                (double)work->cells->n_pairs +
                            6.0 * (double)n));
    PetscCall(PetscLogEventEnd(events.sph_force, 0, 0, 0, 0));
    PetscFunctionReturn(0);
  }
  if (n > work->n_alloc) {
    PetscCall(PetscFree3(work->P, work->inv_rho, work->J));
    work->n_alloc = n + n / 4;
    PetscCall(PetscMalloc3(work->n_alloc, &work->P, work->n_alloc, &work->inv_rho, work->n_alloc,
                           &work->J));
  }
  /* mu_i + mu_j with one liquid of dynamic viscosity rho0 nu */
  const double sqrt_mu_sum = sqrt(2.0 * sp->rho0 * sp->nu);
  for (PetscInt i = 0; i < n; i++) {
    work->inv_rho[i] = 1.0 / ps->rho[i];
    work->P[i] = ps->p[i] * work->inv_rho[i] * work->inv_rho[i];
    work->J[i] = sqrt_mu_sum * work->inv_rho[i];
  }
  const force_args A = {
      .n_pairs = s->cel.n_pairs,
      .pi = s->cel.pair_i,
      .pj = s->cel.pair_j,
      .position = s->cel.position,
      .x = (const double(*)[2])ps->x,
      .v_est = (const double(*)[2])ps->v_est,
      .v_visc = sph_viscous_velocity(ps, work->visc_is_est),
      .mass = ps->mass,
      .rho = ps->rho,
      .P = work->P,
      .inv_rho = work->inv_rho,
      .J = work->J,
      .p = ps->p,
      .a = ps->a,
      .drho = ps->drho,
      .type = ps->type,
      .corr = corr,
      .pair = pair,
      .h = sp->h,
      .inv_h = 1.0 / sp->h,
      .norm = sph_kernel_norm(sp->kernel, 2, sp->h),
      .nu2 = 2.0 * sp->nu,
      .alpha = sp->av_alpha,
      .beta = sp->av_beta,
      .c0 = sp->c0,
      .delta_hs_c0 = sp->delta * 0.5 * sp->h * sp->c0, /* smoothing length h_s = h/2 */
  };
  const int density = continuity ? (sp->delta > 0 ? 2 : 1) : 0;
  const PetscInt64 inside = sweeps[sp->kernel][density][artificial][corr ? 1 : 0](&A);
  if (corr &&
      continuity) /* corrected divergence (sph_correction_iact.h); zero on walls and ghosts */
    for (PetscInt i = 0; i < ps->n_owned; i++)
      ps->drho[i] -= ps->rho[i] * corr[i].div;
  PetscCall(
      PetscLogFlops(sph_force_flops_per_pair(continuity, artificial, density == 2, corr != NULL) *
                        (double)inside +
                    4.0 * (double)n));
  PetscCall(PetscLogEventEnd(events.sph_force, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
