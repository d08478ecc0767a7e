/* Scenes by name (PetscFunctionList) and -help (src/driver/registry.c). */
#ifndef DMHS_REGISTRY_H
#define DMHS_REGISTRY_H
#include <petscsys.h>
#include "dmhs/scene.h"
#include "dmhs/module.h"

struct sim;

PetscErrorCode registry_initialize(void);
PetscErrorCode registry_finalize(void);
PetscErrorCode registry_create_scene(const char *name, scene **out);
/* Comma-separated list of scene names, for -help and error messages. */
PetscErrorCode registry_scene_names(char *buf, size_t len);
/* -help: runs the chosen scene's options pass and its modules' (their values
 * are listed), then every other scene's and module's, and prints each option
 * once (options_help_print). */
PetscErrorCode registry_print_help(struct sim *s, const char *chosen);

#endif
