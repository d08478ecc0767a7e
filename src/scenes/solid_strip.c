/* Two-layer mass-spring strip (see solid_strip.h). */
#include "dmhs/solid_load.h"
#include "solid_strip.h"

PetscErrorCode solid_strip_build(sim *s, solid_strip *st, PetscInt64 *next_gid) {
  const double zero[2] = {0, 0};
  topology *t = s->topo;
  PetscFunctionBeginUser;
  PetscCheck(t, s->comm, PETSC_ERR_ORDER,
             "solid_strip_build: call solid_modules_enable in the scene's options pass");
  PetscCheck(st->n >= st->n_clamp + 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "a strip needs at least 2 free columns (got %" PetscInt_FMT " columns, %" PetscInt_FMT
             " clamped)",
             st->n, st->n_clamp);
  PetscCheck(!st->hinged || st->n_clamp == 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "a hinged strip clamps exactly one column (got %" PetscInt_FMT ")", st->n_clamp);
  st->first_gid = *next_gid;
  for (PetscInt c = 0; c < st->n; c++)
    for (int l = 0; l < 2; l++) {
      const double x[2] = {st->origin[0] + st->spacing * (c * st->along[0] + l * st->across[0]),
                           st->origin[1] + st->spacing * (c * st->along[1] + l * st->across[1])};
      const PetscBool fixed = c < st->n_clamp && !(st->hinged && l == 1) ? PETSC_TRUE : PETSC_FALSE;
      PetscInt i;
      PetscCall(particles_add_owned(&s->ps, (*next_gid)++, fixed ? PTYPE_WALL : PTYPE_SOLID, x,
                                    zero, st->mass, st->rho, &i));
      if (c == st->n - 1 && s->ps.load) /* with solid_load: the tip carries the load */
        s->ps.load[i] = SOLID_LOAD_MARK;
    }
#define G(c, l) (st->first_gid + 2 * (c) + (l))
  for (PetscInt c = 0; c < st->n; c++) {
    const PetscBool free_c = c >= st->n_clamp || st->hinged ? PETSC_TRUE : PETSC_FALSE;
    if (free_c)
      PetscCall(topology_add_bond(t, G(c, 0), G(c, 1), 0));
    if (c + 1 == st->n || c + 1 < st->n_clamp)
      continue; /* cell (c, c+1) touches a free column */
    for (int l = 0; l < 2; l++)
      PetscCall(topology_add_bond(t, G(c, l), G(c + 1, l), 0));
    /* the cell's four corners: centre, then the ends along and across */
    PetscCall(topology_add_angle(t, G(c + 1, 0), G(c, 0), G(c, 1), 0));
    PetscCall(topology_add_angle(t, G(c, 0), G(c + 1, 0), G(c + 1, 1), 0));
    PetscCall(topology_add_angle(t, G(c + 1, 1), G(c, 1), G(c, 0), 0));
    PetscCall(topology_add_angle(t, G(c, 1), G(c + 1, 1), G(c + 1, 0), 0));
  }
#undef G
  PetscFunctionReturn(0);
}

void solid_strip_beam(double k_s, double k_a, double r0, double mass, double *EI, double *kGA,
                      double *mu) {
  *EI = 0.5 * k_s * r0 * r0 * r0 + 2.0 * k_a * r0; /* layers + corner angles (trapezoidal cells) */
  *kGA = 8.0 * k_a / r0;
  *mu = 2.0 * mass / r0;
}
