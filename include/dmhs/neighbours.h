/* Neighbour handling (src/core/neighbours.c): when to rebuild, the rebuild itself
 * (migration, rows re-sorted by cell, ghosts, topology resolution, pair list), the ghost
 * refresh between builds and the restart's rebuild. */
#ifndef DMHS_NEIGHBOURS_H
#define DMHS_NEIGHBOURS_H
#include <petscsys.h>

struct sim;

/* Rebuilds ghosts and pairs for the current positions. */
PetscErrorCode neighbours_rebuild(struct sim *s);
/* Per step: migrate + rebuild when due (or forced), else refresh on the ghosts the fields
 * the modules read there. Collective; force must agree on every rank. */
PetscErrorCode neighbours_update(struct sim *s, PetscBool force);
/* Copies the owned rows' ghost fields, all of them, into their ghosts, so that a
 * diagnostic outside the step sees current neighbour values. */
PetscErrorCode neighbours_refresh_ghosts(struct sim *s);
/* After a restart: rebuilds ghosts and pairs from the positions of the last build
 * (x_build), as the uninterrupted run had them, then refreshes ghosts. */
PetscErrorCode neighbours_rebuild_as_last_built(struct sim *s);
/* Setup, after the modules': the fields a step refreshes on ghosts between builds (the
 * modules' ghost_reads that can change between builds, not FIELD_FIXED). */
PetscErrorCode neighbours_collect_ghost_reads(struct sim *s);

#endif
