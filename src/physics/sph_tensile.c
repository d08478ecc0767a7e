/* Monaghan's artificial pressure against the tensile instability (-sph_tensile_eps;
 * the pair law in sph_tensile_iact.h): a pass over the pair list after the
 * momentum sweep, adding its repulsion to the accelerations. Pairs where neither
 * particle is under tension are skipped, so in a liquid at positive pressure the
 * pass costs one test per pair. */
#include "dmhs/sim.h"
#include "dmhs/events.h"
#include "sph_tensile_iact.h"
#include "sph_force.h"

PetscErrorCode sph_tensile_compute(sim *s, const sph_params *sp, sph_tensile_work *w) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_tensile, 0, 0, 0, 0));
  if (n > w->n_alloc) {
    PetscCall(PetscFree(w->R));
    w->n_alloc = n + n / 4;
    PetscCall(PetscMalloc1(w->n_alloc, &w->R));
  }
  /* every row with a pressure: liquid, solids and walls (their extrapolated p) */
  for (PetscInt i = 0; i < n; i++)
    w->R[i] = sph_tensile_R(sp->tensile_eps, ps->p[i] / (ps->rho[i] * ps->rho[i]));
  const sph_kernel_kind kernel = sp->kernel;
  const double h = sp->h, h2 = h * h, inv_h = 1.0 / h, norm = sph_kernel_norm(kernel, 2, h);
  double w_dx = 0.0, dwdr_dx = 0.0; /* W(dx) > 0: dx < h, checked with the options */
  sph_kernel_eval(kernel, 2, norm, inv_h, s->dx, &w_dx, &dwdr_dx);
  const double inv_w_dx = 1.0 / w_dx;
  const PetscInt *restrict pi = s->cel.pair_i, *restrict pj = s->cel.pair_j;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double *restrict mass = ps->mass, *restrict R = w->R;
  double(*restrict a)[2] = ps->a;
  PetscInt64 active = 0;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = pi[k], j = pj[k];
    const double R_sum = R[i] + R[j];
    if (R_sum == 0.0)
      continue; /* neither under tension */
    const double rij[2] = {x[i][0] - x[j][0], x[i][1] - x[j][1]};
    const double r2 = PetscMax(rij[0] * rij[0] + rij[1] * rij[1], SPH_R2_FLOOR * h2);
    if (r2 >= h2)
      continue;
    const double r = sqrt(r2);
    double wr = 0.0, dwdr = 0.0, T[2];
    sph_kernel_eval(kernel, 2, norm, inv_h, r, &wr, &dwdr);
    sph_tensile_iact(rij, dwdr / r, wr, inv_w_dx, R_sum, T);
    /* ghost rows' sums are discarded, as in the momentum sweep */
    a[i][0] += mass[j] * T[0];
    a[i][1] += mass[j] * T[1];
    a[j][0] -= mass[i] * T[0];
    a[j][1] -= mass[i] * T[1];
    active++;
  }
  PetscCall(PetscLogFlops(30.0 * (double)active + 4.0 * (double)n));
  PetscCall(PetscLogEventEnd(events.sph_tensile, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode sph_tensile_destroy(sph_tensile_work *w) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(w->R));
  w->n_alloc = 0;
  PetscFunctionReturn(0);
}
