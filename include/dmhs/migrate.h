/* Keeping owned particles where they belong: periodic wrapping, the escape
 * check along closed directions, and (across ranks) moving them to new owners. */
#ifndef DMHS_MIGRATE_H
#define DMHS_MIGRATE_H
#include <petscsys.h>

struct sim;
PetscErrorCode migrate_particles(struct sim *s);

#endif
