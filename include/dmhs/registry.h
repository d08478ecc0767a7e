/* Scenes and physics modules by name (PetscFunctionList). */
#ifndef DMHS_REGISTRY_H
#define DMHS_REGISTRY_H
#include <petscsys.h>
#include "dmhs/scene.h"
#include "dmhs/module.h"

struct sim;

PetscErrorCode registry_initialize(void);
PetscErrorCode registry_finalize(void);
PetscErrorCode registry_create_scene(const char *name, scene **out);
PetscErrorCode registry_create_module(const char *name, module **out);
/* Comma-separated list of scene names, for -help and error messages. */
PetscErrorCode registry_scene_names(char *buf, size_t len);
/* Runs every scene's and module's options pass so -help lists them all. */
PetscErrorCode registry_print_help(struct sim *s);

#endif
