/* Summation density: rho_i = sum_j m_j W_ij, self term included, for owned
 * fluid and solid particles (walls get theirs from sph_wall.c). The
 * continuity form is accumulated inside the force sweep (sph_force.c). */
#include "dmhs/events.h"
#include "sph_kernel.h"
#include "sph_force.h"

SPH_INLINE void density_sweep(sph_kernel_kind kernel, sim *s, double h, double norm) {
  particles *ps = &s->ps;
  const PetscInt *restrict pi = s->cel.pair_i, *restrict pj = s->cel.pair_j;
  const double(*restrict x)[2] = (const double(*)[2])ps->x;
  const double *restrict mass = ps->mass;
  double *restrict rho = ps->rho;
  const double inv_h = 1.0 / h;
  double w0, dw0;
  sph_kernel_eval(kernel, 2, norm, inv_h, 0.0, &w0, &dw0);
  for (PetscInt i = 0; i < ps->n_owned + ps->n_ghost; i++)
    if (ps->type[i] != PTYPE_WALL)
      rho[i] = mass[i] * w0;
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = pi[k], j = pj[k];
    const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], r2 = dx * dx + dy * dy;
    if (r2 * inv_h * inv_h >= 1.0)
      continue; /* in the list's skin only */
    double w, dwdr;
    sph_kernel_eval(kernel, 2, norm, inv_h, sqrt(r2), &w, &dwdr);
    /* wall rows are overwritten by the wall pass; ghost rows are refreshed below */
    rho[i] += mass[j] * w;
    rho[j] += mass[i] * w;
  }
}

static void density_lucy(sim *s, double h, double n) {
  density_sweep(SPH_KERNEL_LUCY, s, h, n);
}
static void density_cubic(sim *s, double h, double n) {
  density_sweep(SPH_KERNEL_CUBIC, s, h, n);
}
static void density_wendland(sim *s, double h, double n) {
  density_sweep(SPH_KERNEL_WENDLAND, s, h, n);
}

PetscErrorCode sph_density_summation(sim *s, const sph_params *sp) {
  static const char *const refreshed[] = {"rho"};
  static void (*const sweeps[])(sim *, double, double) = {density_lucy, density_cubic,
                                                          density_wendland};
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_density, 0, 0, 0, 0));
  sweeps[sp->kernel](s, sp->h, sph_kernel_norm(sp->kernel, 2, sp->h));
  PetscCall(PetscLogFlops(20.0 * (double)s->cel.n_pairs));
  PetscCall(PetscLogEventEnd(events.sph_density, 0, 0, 0, 0));
  /* a ghost only saw the pairs its rank owns: take its owner's full sum */
  PetscCall(halo_forward(&s->hal, &s->ps, refreshed, 1));
  PetscFunctionReturn(0);
}
