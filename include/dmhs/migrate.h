/* Keeping owned particles where they belong: periodic wrapping, the escape
 * check along closed directions, and (across ranks) moving them to the owners
 * of their coarse cells (partition.h). */
#ifndef DMHS_MIGRATE_H
#define DMHS_MIGRATE_H
#include <stdint.h>
#include <petscsys.h>

struct sim;

/* -debug_migration: the global count and id-set fingerprint taken at setup. */
typedef struct migrate_check {
  PetscBool enabled, have_reference;
  uint64_t reference[3]; /* count, sum of gids, sum of hash(gid), modulo 2^64 */
  PetscInt64 moved;      /* particles sent to another rank by this rank, whole run */
} migrate_check;

/* Reads -debug_migration. */
PetscErrorCode migrate_set_from_options(migrate_check *m, struct sim *s);
/* Wraps, checks escape, repartitions when due, moves particles to their owners;
 * with -debug_migration checks the id set. Collective. */
PetscErrorCode migrate_particles(struct sim *s);
/* With -debug_migration: the first call takes the reference, later ones compare
 * (error naming the step). Collective. */
PetscErrorCode migrate_check_ids(migrate_check *m, struct sim *s);

/* With -debug_migration: prints how many particles changed rank during the run. */
PetscErrorCode migrate_report(migrate_check *m, struct sim *s);

#endif
