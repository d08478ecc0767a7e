/* The field table: the single place that says, for every per-particle array,
 * whether it migrates, goes to ghosts, is checkpointed and is written out.
 * Adding a particle quantity = one row here + one member in struct particles.
 *
 * Rows flagged FIELD_OPTIONAL exist only when a scene or module asks for them
 * (fields_enable, before the first particle is added): a case without solid
 * bodies or stress diagnostics allocates, migrates and writes none of them.
 * fields_table() lists the active rows only, so every loop over the table
 * (allocation, packing, checkpoint, snapshots, XDMF) follows. */
#include <string.h>
#include "dmhs/fields.h"
#include "dmhs/particles.h"
#include <petscsys.h>

#define ALL (FIELD_MIGRATE | FIELD_GHOST | FIELD_CHECKPOINT | FIELD_OUTPUT)
#define ROW(member, w, k, fl, u)                                                                   \
  { #member, w, k, offsetof(particles, member), fl, u }

static const field_desc table[] = {
    ROW(gid, 1, FIELD_INT64, ALL | FIELD_FIXED, "1"),
    ROW(type, 1, FIELD_INT, ALL | FIELD_FIXED, "1"),
    ROW(x, DMHS_DIM, FIELD_REAL, ALL, "m"),
    ROW(v, DMHS_DIM, FIELD_REAL, ALL, "m/s"),
    /* v_est is derived (v + dt a) in the first half step: not checkpointed. */
    ROW(v_est, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_GHOST, "m/s"),
    /* v_visc is rebuilt by the wall pass before every force sweep; optional: without walls
     * the viscous term reads v_est, and a scene that says so (sph_set_no_walls) has none */
    ROW(v_visc, DMHS_DIM, FIELD_REAL, FIELD_GHOST | FIELD_OPTIONAL, "m/s"),
    /* a and drho are needed by the first kick after a restart. */
    ROW(a, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT, "m/s^2"),
    /* optional: the initial position, for those who anchor to it or measure from it */
    ROW(x0, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL,
        "m"),
    /* positions at the last neighbour build: decide the next rebuild, and let a
     * restart rebuild the very same ghosts and pairs (bitwise restart) */
    ROW(x_build, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT, "m"),
    ROW(mass, 1, FIELD_REAL, ALL | FIELD_FIXED, "kg"),
    ROW(rho, 1, FIELD_REAL, ALL, "kg/m^3"),
    ROW(drho, 1, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL,
        "kg/m^3/s"),
    /* drho and p are the SPH module's (it enables them): a run without liquid has neither.
     * p is recomputed before use; checkpointed so a restarted state is complete */
    ROW(p, 1, FIELD_REAL, FIELD_GHOST | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL, "Pa"),
    /* optional: which solid body a particle belongs to (0 = none / walls), so
     * that repulsion can keep two bodies (the vein's leaflets) apart */
    ROW(body, 1, FIELD_INT, ALL | FIELD_OPTIONAL | FIELD_FIXED, "1"),
    /* optional: per-particle stress diagnostics (src/diag/stress.c), derived at
     * output times from the current state, hence neither migrated nor saved */
    ROW(shear_rate, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "1/s"),
    ROW(stress_xx, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "Pa"),
    ROW(stress_xy, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "Pa"),
    ROW(stress_yy, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "Pa"),
    ROW(stress_mag, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "Pa"),
    ROW(pressure_force, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "N/m"),
    ROW(speed, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "m/s"),
    ROW(displacement, 1, FIELD_REAL, FIELD_OUTPUT | FIELD_OPTIONAL, "m"),
    /* optional: a wall particle's vector to the nearest point of the wall
     * surface, set by scenes that know their walls' geometry (the channel), for
     * -sph_wall_extrapolation quadratic; constant for a wall moving rigidly */
    ROW(to_surface, DMHS_DIM, FIELD_REAL,
        FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL, "m"),
    /* optional: side of the leaflet a fluid particle was last seen beside
     * (+-1 the upper, +-2 the lower; 0 = beside none), for the vein's crossing count */
    ROW(side, 1, FIELD_INT, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OPTIONAL, "1"),
    /* optional (-solid_substeps): set by the force evaluation, used by the
     * next step's sub-steps; checkpointed so a restart continues them */
    ROW(a_hold, DMHS_DIM, FIELD_REAL, FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OPTIONAL, "m/s^2"),
    /* optional (-solid_substeps): 1 on the rows that move on the sub-steps (the solids, and the
     * liquid in a sub-cycled contact), marked at the start of every step; migrates, as the
     * step's second kick (after a rebuild) reads it; a step never spans a checkpoint */
    ROW(substepped, 1, FIELD_INT, FIELD_MIGRATE | FIELD_OPTIONAL, "1"),
    /* optional (-sph_density_predict): the step's first density rate, set in the
     * first half step and used in the second; a step never spans a checkpoint */
    ROW(drho_prev, 1, FIELD_REAL, FIELD_MIGRATE | FIELD_OPTIONAL, "kg/m^3/s"),
    /* optional named marks (one per use, each enabled by its user; 0 = none): solid_load's
     * loaded particles, peristalsis' membrane segments (1 + pocket), a scene's tracked
     * liquid; set when the scene is built, never read on ghosts */
    ROW(load, 1, FIELD_INT,
        FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL | FIELD_FIXED, "1"),
    ROW(segment, 1, FIELD_INT,
        FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL | FIELD_FIXED, "1"),
    ROW(tracer, 1, FIELD_INT,
        FIELD_MIGRATE | FIELD_CHECKPOINT | FIELD_OUTPUT | FIELD_OPTIONAL | FIELD_FIXED, "1"),
};

#define N_ROWS (sizeof(table) / sizeof(table[0]))
static PetscBool enabled[N_ROWS];
static field_desc active[N_ROWS];
static size_t n_active;
static PetscBool frozen; /* particles exist: the set of rows can no longer change */

static void fields_collect(void) {
  n_active = 0;
  for (size_t k = 0; k < N_ROWS; k++)
    if (!(table[k].flags & FIELD_OPTIONAL) || enabled[k])
      active[n_active++] = table[k];
}

const field_desc *fields_table(size_t *count) {
  if (!n_active)
    fields_collect();
  *count = n_active;
  return active;
}

PetscErrorCode fields_enable(const char *name) {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < N_ROWS; k++) {
    if (strcmp(table[k].name, name))
      continue;
    PetscCheck(table[k].flags & FIELD_OPTIONAL, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "fields_enable: field %s always exists", name);
    if (enabled[k])
      PetscFunctionReturn(0);
    PetscCheck(
        !frozen, PETSC_COMM_SELF, PETSC_ERR_ORDER,
        "fields_enable(%s): particles already exist; enable fields in the scene's options pass",
        name);
    enabled[k] = PETSC_TRUE;
    fields_collect();
    PetscFunctionReturn(0);
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "fields_enable: no field named %s", name);
}

PetscBool fields_enabled(const char *name) {
  return fields_find(name) ? PETSC_TRUE : PETSC_FALSE;
}

void fields_freeze(PetscBool on) {
  frozen = on;
}

void fields_reset(void) {
  for (size_t k = 0; k < N_ROWS; k++)
    enabled[k] = PETSC_FALSE;
  frozen = PETSC_FALSE;
  fields_collect();
}

size_t fields_row_bytes(const field_desc *f) {
  size_t elem = f->kind == FIELD_REAL  ? sizeof(double)
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
    if (!strcmp(t[k].name, name))
      return &t[k];
  return NULL;
}
