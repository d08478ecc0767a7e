/* The solids' fastest mode: a Gershgorin bound from the sub-cycled modules'
 * Jacobian blocks (see include/dmhs/solid_modes.h). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/solid_modes.h"

/* partners of a row: its 1-2 and 1-3 neighbours and itself (a two-layer strip
 * has at most 7, a three-layer membrane 10) */
#define SOLID_MODES_PARTNERS 24

typedef struct {
  PetscInt64 gid;
  double b[2][2];
} jacobian_slot;

struct solid_jacobian {
  const particles *ps;
  PetscInt *table;      /* per owned row: its table, or -1 */
  PetscInt *n_partners; /* per table */
  jacobian_slot *slots; /* SOLID_MODES_PARTNERS per table */
  PetscInt n_tables, capacity;
};

static int row_moves(const particles *ps, PetscInt i) {
  return ps->type[i] != PTYPE_WALL;
}

PetscErrorCode solid_jacobian_add(solid_jacobian *J, PetscInt p, PetscInt q, const double B[2][2]) {
  const particles *ps = J->ps;
  PetscFunctionBeginUser;
  if (p >= ps->n_owned || !row_moves(ps, p) || !row_moves(ps, q))
    PetscFunctionReturn(0);
  if (J->table[p] < 0) {
    if (J->n_tables == J->capacity) {
      const PetscInt grown = PetscMax(64, 2 * J->capacity);
      PetscCall(PetscRealloc(sizeof(*J->n_partners) * (size_t)grown, &J->n_partners));
      PetscCall(PetscRealloc(sizeof(*J->slots) * (size_t)grown * SOLID_MODES_PARTNERS, &J->slots));
      J->capacity = grown;
    }
    J->n_partners[J->n_tables] = 0;
    J->table[p] = J->n_tables++;
  }
  const PetscInt t = J->table[p];
  jacobian_slot *slot = J->slots + t * SOLID_MODES_PARTNERS;
  PetscInt k = 0;
  while (k < J->n_partners[t] && slot[k].gid != ps->gid[q])
    k++;
  if (k == J->n_partners[t]) {
    PetscCheck(k < SOLID_MODES_PARTNERS, PETSC_COMM_SELF, PETSC_ERR_SUP,
               "particle gid %" PetscInt64_FMT " has more than %d bonded partners: raise "
               "SOLID_MODES_PARTNERS (src/core/solid_modes.c)",
               ps->gid[p], SOLID_MODES_PARTNERS);
    slot[k].gid = ps->gid[q];
    PetscCall(PetscArrayzero(&slot[k].b[0][0], 4));
    J->n_partners[t]++;
  }
  for (int r = 0; r < 2; r++)
    for (int c = 0; c < 2; c++)
      slot[k].b[r][c] += B[r][c];
  PetscFunctionReturn(0);
}

/* the spectral norm of a 2x2 block: the root of the largest eigenvalue of B^T B */
static double block_norm(const double b[2][2]) {
  const double p = b[0][0] * b[0][0] + b[1][0] * b[1][0], r = b[0][1] * b[0][1] + b[1][1] * b[1][1],
               q = b[0][0] * b[0][1] + b[1][0] * b[1][1];
  return sqrt(0.5 * (p + r) + sqrt(0.25 * (p - r) * (p - r) + q * q));
}

PetscErrorCode solid_modes_omega_bound(sim *s, double *omega) {
  const particles *ps = &s->ps;
  solid_jacobian J = {.ps = ps};
  double local = 0, global;
  PetscBool any = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(ps->n_owned + 1, &J.table));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    J.table[i] = -1;
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->solid_internal && s->modules[m]->jacobian_blocks) {
      PetscCall(s->modules[m]->jacobian_blocks(s->modules[m], s, &J));
      any = PETSC_TRUE;
    }
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (J.table[i] < 0)
      continue;
    const jacobian_slot *slot = J.slots + J.table[i] * SOLID_MODES_PARTNERS;
    double row = 0;
    for (PetscInt k = 0; k < J.n_partners[J.table[i]]; k++)
      row += block_norm(slot[k].b);
    local = PetscMax(local, row / ps->mass[i]);
  }
  PetscCall(PetscFree(J.table));
  PetscCall(PetscFree(J.n_partners));
  PetscCall(PetscFree(J.slots));
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *omega = any ? sqrt(global) : 0;
  PetscFunctionReturn(0);
}

PetscErrorCode solid_modes_add_limit(sim *s, dt_limits *l) {
  double omega;
  PetscFunctionBeginUser;
  const double factor = s->substeps.mode_factor;
  if (!s->substeps.on || !(factor > 0))
    PetscFunctionReturn(0);
  PetscCall(solid_modes_omega_bound(s, &omega));
  if (omega > 0) {
    char formula[96];
    PetscCall(PetscSNPrintf(formula, sizeof(formula),
                            "%g/omega, omega: Gershgorin bound of the solids' M^-1 dF/dx", factor));
    PetscCall(dt_limits_add(l, "solid fastest mode", formula, factor / omega));
  }
  PetscFunctionReturn(0);
}
