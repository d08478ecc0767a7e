/* The clot bonds (agglomeration.c): U = K (r - r0_b)^2 for every local bond
 * entry of the bond type the agglomeration module claimed, r0_b the bond's own rest length (its
 * length when it was made, topology bond_r0), so that a new bond starts with
 * zero energy and force. Same arithmetic as bond_harmonic (bond_iact.h). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/agglomeration.h"
#include "bond_iact.h"
#include "virial_iact.h"

PetscErrorCode bond_clot_compute(sim *s, const void *owner, double K) {
  const topology *t = s->topo;
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    if (t->bond_owner[t->bond_ltype[b]] != owner)
      continue;
    const PetscInt i = t->bond[b][0], j = t->bond[b][1];
    const double d[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double fr =
        bond_harmonic_iact(K, t->bond_r0[t->bond_index[b]], sqrt(d[0] * d[0] + d[1] * d[1]));
    const double fi = fr / ps->mass[i], fj = fr / ps->mass[j];
    ps->a[i][0] += fi * d[0];
    ps->a[i][1] += fi * d[1];
    ps->a[j][0] -= fj * d[0];
    ps->a[j][1] -= fj * d[1];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode bond_clot_virial(sim *s, const void *owner, double K, double (*W)[3]) {
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    if (t->bond_owner[t->bond_ltype[b]] != owner)
      continue;
    const PetscInt i = t->bond[b][0], j = t->bond[b][1];
    const double d[2] = {ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]};
    const double fr = bond_harmonic_iact(K, t->bond_r0[t->bond_index[b]], hypot(d[0], d[1]));
    virial_pair_add(W, i, j, fr, d);
  }
  PetscFunctionReturn(0);
}

double bond_clot_energy_local(sim *s, const void *owner, double K) {
  const topology *t = s->topo;
  const particles *ps = &s->ps;
  double e = 0;
  for (PetscInt b = 0; b < t->n_bond_local; b++) {
    if (t->bond_owner[t->bond_ltype[b]] != owner)
      continue;
    const PetscInt i = t->bond[b][0], j = t->bond[b][1];
    const double r = hypot(ps->x[i][0] - ps->x[j][0], ps->x[i][1] - ps->x[j][1]);
    e += t->bond_weight[b] * bond_harmonic_energy(K, t->bond_r0[t->bond_index[b]], r);
  }
  return e;
}
