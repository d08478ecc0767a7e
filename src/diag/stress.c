/* Per-particle stress diagnostics: the virial (mechanical) stress of every
 * particle, as LAMMPS' compute stress/atom divided by the particle's volume,
 *   sigma_i = -(1 / V_i) [ 1/2 sum_pairs r_ij (x) F_ij + bonds + 1/3 angles ],
 *   V_i = m_i / rho_i (2D: per unit depth),
 * summed over the modules that define a virial (SPH pressure and viscosity,
 * repulsion, bonds, angles; module.h), without the kinetic term: it is the
 * stress the particle's neighbours exert, negative in compression. Its
 * magnitude is the Frobenius norm |sigma| = sqrt(xx^2 + 2 xy^2 + yy^2), which
 * at rest under a pressure p is sqrt(2) p. The SPH module also fills the
 * shear rate and the pressure force (src/physics/sph_stress.c). doc/theory.md,
 * "Stress diagnostics". */
#include <math.h>
#include "dmhs/stress.h"
#include "dmhs/fields.h"

static const char *const stress_fields[] = {"shear_rate", "stress_xx",   "stress_xy",
                                            "stress_yy",  "stress_mag",  "pressure_force",
                                            "speed",      "displacement"};

PetscErrorCode stress_enable(void) {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(stress_fields) / sizeof(stress_fields[0]); k++)
    PetscCall(fields_enable(stress_fields[k]));
  PetscCall(fields_enable("x0")); /* the displacement field */
  PetscFunctionReturn(0);
}

PetscErrorCode stress_compute(sim *s) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  double(*W)[3];
  PetscFunctionBeginUser;
  PetscCheck(ps->stress_mag, s->comm, PETSC_ERR_ORDER,
             "stress_compute: the scene did not call stress_enable");
  /* ghosts carry rho, p and v_visc as the last force evaluation left them,
   * while an owner's rho has had its second kick since: a pair across ranks
   * would then see other values than the same pair inside one rank. The
   * owners' current values, forwarded, make the fields independent of the rank
   * count (the next step refreshes the ghosts anyway). */
  static const char *const current[] = {"rho", "p", "v_visc"};
  PetscCall(halo_forward(&s->hal, ps, current, 3));
  PetscCall(PetscCalloc1(n + 1, &W));
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->virial)
      PetscCall(s->modules[m]->virial(s->modules[m], s, W));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const double inv_v = ps->rho[i] / ps->mass[i];
    ps->stress_xx[i] = W[i][0] * inv_v;
    ps->stress_xy[i] = W[i][1] * inv_v;
    ps->stress_yy[i] = W[i][2] * inv_v;
    ps->stress_mag[i] =
        sqrt(ps->stress_xx[i] * ps->stress_xx[i] + 2.0 * ps->stress_xy[i] * ps->stress_xy[i] +
             ps->stress_yy[i] * ps->stress_yy[i]);
    ps->speed[i] = hypot(ps->v[i][0], ps->v[i][1]);
    double d[2] = {ps->x[i][0] - ps->x0[i][0], ps->x[i][1] - ps->x0[i][1]};
    domain_min_image(&s->dom, d);
    ps->displacement[i] = hypot(d[0], d[1]);
  }
  PetscCall(PetscFree(W));
  PetscFunctionReturn(0);
}
