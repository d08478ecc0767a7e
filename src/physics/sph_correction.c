/* -sph_kernel_correction: the per-particle tensors of the corrected pressure
 * gradient and viscous Laplacian (arithmetic and reasons in
 * sph_correction_iact.h), from one pass over the pairs after the wall pass
 * (the walls' viscous velocities enter the velocity gradient).
 *
 * Only owned non-wall rows get tensors: a ghost's sums are incomplete (its
 * rank lists only some of its pairs), but its share of a pair is discarded
 * by the force sweep anyway, and walls are not integrated. Both are given
 * zero tensors, so their (discarded) pair terms are zero, never NaN. */
#include "dmhs/events.h"
#include "sph_correction_iact.h"
#include "sph_force.h"

typedef const double (*vel_rows)[2];
typedef double (*pair_rows)[2];

SPH_INLINE void moments_sweep(sph_kernel_kind kernel, sim *s, double h, vel_rows vv,
                              const double *restrict vol, const double (*restrict e)[2],
                              sph_moments *restrict mom, double (*restrict pair)[2]) {
  const particles *ps = &s->ps;
  const PetscInt *restrict pi = s->cel.pair_i, *restrict pj = s->cel.pair_j;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double(*restrict v)[2] = vv;
  const PetscInt *restrict type = ps->type;
  const double h2 = h * h, inv_h = 1.0 / h, norm = sph_kernel_norm(kernel, 2, h);
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = pi[k], j = pj[k];
    const double xij[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double r2 = PetscMax(xij[0] * xij[0] + xij[1] * xij[1], SPH_R2_FLOOR * h2);
    if (r2 >= h2) { /* in the list's skin only */
      pair[k][0] = pair[k][1] = 0.0;
      continue;
    }
    const double r = sqrt(r2), inv_r2 = 1.0 / r2;
    double w, dwdr;
    sph_kernel_eval(kernel, 2, norm, inv_h, r, &w, &dwdr);
    const double F = dwdr * (r * inv_r2);
    pair[k][0] = F; /* the force sweep reuses them: no second sqrt, division and kernel */
    pair[k][1] = inv_r2;
    const double vji[2] = {v[j][0] - v[i][0], v[j][1] - v[i][1]};
    const double xji[2] = {-xij[0], -xij[1]}, vij[2] = {-vji[0], -vji[1]};
    const double Vi = vol[i] < 0.0 ? -vol[i] : vol[i], Vj = vol[j] < 0.0 ? -vol[j] : vol[j];
    /* only owned non-wall rows use their moments (header comment) */
    if (vol[i] > 0.0)
      sph_moments_pair(xij, F, inv_r2, vji, Vj, &mom[i]);
    if (vol[j] > 0.0)
      sph_moments_pair(xji, F, inv_r2, vij, Vi, &mom[j]);
    if (type[i] == PTYPE_WALL || type[j] == PTYPE_WALL) {
      const double eji[2] = {e[j][0] - e[i][0], e[j][1] - e[i][1]}, eij[2] = {-eji[0], -eji[1]};
      if (vol[i] > 0.0)
        sph_moments_pair_wall(xij, F, eji, Vj, &mom[i]);
      if (vol[j] > 0.0)
        sph_moments_pair_wall(xji, F, eij, Vi, &mom[j]);
    }
  }
}

static void moments_lucy(sim *s, double h, vel_rows vv, const double *V, vel_rows vd,
                         sph_moments *m, pair_rows p) {
  moments_sweep(SPH_KERNEL_LUCY, s, h, vv, V, vd, m, p);
}
static void moments_cubic(sim *s, double h, vel_rows vv, const double *V, vel_rows vd,
                          sph_moments *m, pair_rows p) {
  moments_sweep(SPH_KERNEL_CUBIC, s, h, vv, V, vd, m, p);
}
static void moments_wendland(sim *s, double h, vel_rows vv, const double *V, vel_rows vd,
                             sph_moments *m, pair_rows p) {
  moments_sweep(SPH_KERNEL_WENDLAND, s, h, vv, V, vd, m, p);
}

/* e = v_div - v_visc of a row: the divergence sees v_visc, but a wall's own
 * velocity, as the plain continuity equation does (sph_correction_iact.h). */
static void divergence_shift(const particles *ps, PetscInt i, double e[2]) {
  const PetscBool wall = ps->type[i] == PTYPE_WALL ? PETSC_TRUE : PETSC_FALSE;
  e[0] = wall ? ps->v[i][0] - ps->v_visc[i][0] : 0.0;
  e[1] = wall ? ps->v[i][1] - ps->v_visc[i][1] : 0.0;
}

PetscErrorCode sph_correction_compute(sim *s, const sph_params *sp, const double (*vv)[2],
                                      sph_correction_work *w) {
  static void (*const sweeps[])(sim *, double, vel_rows, const double *, vel_rows, sph_moments *,
                                pair_rows) = {moments_lucy, moments_cubic, moments_wendland};
  const particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_correction, 0, 0, 0, 0));
  if (n > w->n_alloc) {
    PetscCall(PetscFree4(w->mom, w->corr, w->vol, w->e_div));
    w->n_alloc = n + n / 4;
    PetscCall(PetscMalloc4(w->n_alloc, &w->mom, w->n_alloc, &w->corr, w->n_alloc, &w->vol,
                           w->n_alloc, &w->e_div));
  }
  if (s->cel.n_pairs > w->n_pair_alloc) {
    PetscCall(PetscFree(w->pair));
    w->n_pair_alloc = s->cel.n_pairs + s->cel.n_pairs / 4;
    PetscCall(PetscMalloc1(w->n_pair_alloc, &w->pair));
  }
  PetscCall(PetscArrayzero(w->mom, n));
  PetscCall(PetscArrayzero(w->corr, n));
  for (PetscInt i = 0; i < n; i++) {
    /* the sign marks the rows whose moments are needed: owned, not walls */
    const double V = ps->mass[i] / ps->rho[i];
    w->vol[i] = i < ps->n_owned && ps->type[i] != PTYPE_WALL ? V : -V;
    divergence_shift(ps, i, w->e_div[i]);
  }
  sweeps[sp->kernel](s, sp->h, vv, w->vol, (vel_rows)w->e_div, w->mom, w->pair);
  /* a sparse neighbourhood falls back to the plain operators (sph_correction_iact.h) */
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] != PTYPE_WALL)
      (void)sph_correction_from_moments(&w->mom[i], &w->corr[i]);
  PetscCall(PetscLogFlops(120.0 * (double)s->cel.n_pairs + 150.0 * (double)ps->n_owned));
  PetscCall(PetscLogEventEnd(events.sph_correction, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode sph_correction_destroy(sph_correction_work *w) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(w->mom, w->corr, w->vol, w->e_div));
  PetscCall(PetscFree(w->pair));
  w->n_alloc = w->n_pair_alloc = 0;
  PetscFunctionReturn(0);
}
