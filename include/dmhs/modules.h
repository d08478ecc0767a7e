/* The physics modules by name (src/physics/modules.c). */
#ifndef DMHS_MODULES_H
#define DMHS_MODULES_H
#include <stddef.h>
#include <petscsys.h>
#include "dmhs/module.h"

struct sim;

/* A new module of that name; PETSC_ERR_ARG_UNKNOWN_TYPE when there is none. */
PetscErrorCode modules_create(const char *name, module **out);
/* The registered modules, in table order (-help lists them all). */
size_t modules_count(void);
const char *modules_name(size_t k);
/* Called by scenes: adds the module of that name to the run (its options pass runs after the
 * scene's, so the scene sets its defaults first); out may be NULL. */
PetscErrorCode modules_enable(struct sim *s, const char *name, module **out);

#endif
