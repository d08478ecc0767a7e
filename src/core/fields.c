/* The field table: the single place that says, for every per-particle array,
 * whether it migrates, goes to ghosts, is checkpointed and is written out.
 * Adding a particle quantity = one row here + one member in struct particles. */
#include <string.h>
#include "dmhs/fields.h"
#include "dmhs/particles.h"

#define ALL (FIELD_MIGRATE | FIELD_GHOST | FIELD_CHECKPOINT | FIELD_OUTPUT)
#define ROW(member, w, k, fl, u) {#member, w, k, offsetof(particles, member), fl, u}

static const field_desc table[] = {
    ROW(gid, 1, FIELD_INT64, ALL, "1"),
    ROW(type, 1, FIELD_INT, ALL, "1"),
    ROW(tag, 1, FIELD_INT, ALL, "1"),
    ROW(x, DMHS_DIM, FIELD_REAL, ALL, "m"),
    ROW(v, DMHS_DIM, FIELD_REAL, ALL, "m/s"),
    /* v_est is derived (v + dt a) in the first half step: not checkpointed. */
    ROW(v_est, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_GHOST, "m/s"),
    /* v_visc is rebuilt by the wall pass before every force sweep. */
    ROW(v_visc, DMHS_DIM, FIELD_REAL, FIELD_GHOST, "m/s"),
    /* a and drho are needed by the first kick after a restart. */
    ROW(a, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT, "m/s^2"),
    ROW(x0, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT, "m"),
    /* positions at the last neighbour build: decide the next rebuild, and let a
     * restart rebuild the very same ghosts and pairs (bitwise restart) */
    ROW(x_build, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT, "m"),
    ROW(mass, 1, FIELD_REAL, ALL, "kg"),
    ROW(rho, 1, FIELD_REAL, ALL, "kg/m^3"),
    ROW(drho, 1, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT, "kg/m^3/s"),
    /* p is recomputed before use; checkpointed so a restarted state is complete */
    ROW(p, 1, FIELD_REAL, FIELD_GHOST | FIELD_CHECKPOINT | FIELD_OUTPUT, "Pa"),
};

const field_desc *fields_table(size_t *count) {
  *count = sizeof(table) / sizeof(table[0]);
  return table;
}

size_t fields_row_bytes(const field_desc *f) {
  size_t elem = f->kind == FIELD_REAL ? sizeof(double)
                : f->kind == FIELD_INT ? sizeof(PetscInt)
                                       : sizeof(PetscInt64);
  return elem * (size_t)f->width;
}

void **fields_member(void *particles_struct, const field_desc *f) {
  return (void **)((char *)particles_struct + f->offset);
}

const field_desc *fields_find(const char *name) {
  size_t n;
  const field_desc *t = fields_table(&n);
  for (size_t k = 0; k < n; k++)
    if (!strcmp(t[k].name, name)) return &t[k];
  return NULL;
}
