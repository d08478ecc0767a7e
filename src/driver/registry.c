/* Scenes by name (PetscFunctionList), so -scene picks a builder, and -help, which lists
 * every scene's and module's options. The table below is the only place a new scene is
 * registered (modules: src/physics/modules.c). */
#include <string.h>
#include "dmhs/registry.h"
#include "dmhs/sim.h"
#include "dmhs/strbuf.h"
#include "dmhs/scenes.h"
#include "dmhs/modules.h"

static const struct {
  const char *name;
  PetscErrorCode (*create)(scene **);
} scene_table[] = {
    {"poiseuille", poiseuille_scene_create},
    {"couette", couette_scene_create},
    {"box", box_scene_create},
    {"cantilever", cantilever_scene_create}, /* solids */
    {"flap", flap_scene_create},
    {"intestine", intestine_scene_create}, /* doc/cases.md */
    {"vein", vein_scene_create},
    {"peristaltic_channel", peristaltic_channel_scene_create}, /* oracle: Shapiro et al. */
};

#define N_SCENES (sizeof(scene_table) / sizeof(scene_table[0]))

static PetscFunctionList scene_list;

PetscErrorCode registry_initialize(void) {
  PetscFunctionBeginUser;
  if (scene_list)
    PetscFunctionReturn(0);
  for (size_t k = 0; k < N_SCENES; k++)
    PetscCall(PetscFunctionListAdd(&scene_list, scene_table[k].name, scene_table[k].create));
  PetscFunctionReturn(0);
}

PetscErrorCode registry_finalize(void) {
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&scene_list));
  PetscFunctionReturn(0);
}

PetscErrorCode registry_scene_names(char *buf, size_t len) {
  PetscFunctionBeginUser;
  buf[0] = 0;
  for (size_t k = 0; k < N_SCENES; k++) {
    if (k)
      PetscCall(strbuf_cat(buf, len, ", "));
    PetscCall(strbuf_cat(buf, len, scene_table[k].name));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode registry_create_scene(const char *name, scene **out) {
  PetscErrorCode (*create)(scene **) = NULL;
  char names[256];
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListFind(scene_list, name, &create));
  PetscCall(registry_scene_names(names, sizeof(names)));
  PetscCheck(create, PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE,
             "-scene %s: unknown scene (choose one of: %s)", name, names);
  PetscCall(create(out));
  PetscFunctionReturn(0);
}

/* -help: the options pass of scene k, then of each module it enables that has
 * not had its pass yet; modules destroyed after (a pass may look at the others). */
static PetscErrorCode registry_help_scene(sim *s, size_t k, PetscBool printed[]) {
  scene *scn;
  PetscFunctionBeginUser;
  PetscCall(registry_create_scene(scene_table[k].name, &scn));
  PetscCall(scn->set_from_options(scn, s));
  for (int m = 0; m < s->n_modules; m++) {
    for (size_t j = 0; j < modules_count(); j++)
      if (!strcmp(modules_name(j), s->modules[m]->name) && !printed[j]) {
        PetscCall(s->modules[m]->set_from_options(s->modules[m], s));
        printed[j] = PETSC_TRUE;
      }
  }
  for (int m = 0; m < s->n_modules; m++) {
    PetscCall(s->modules[m]->destroy(s->modules[m]));
    PetscCall(PetscFree(s->modules[m]));
  }
  s->n_modules = 0;
  PetscCall(scn->destroy(scn));
  PetscCall(PetscFree(scn));
  PetscFunctionReturn(0);
}

PetscErrorCode registry_print_help(sim *s, const char *chosen) {
  static char note[96];
  PetscBool printed[32] = {PETSC_FALSE}, user_style;
  size_t first = N_SCENES;
  PetscFunctionBeginUser;
  PetscCheck(modules_count() <= sizeof(printed) / sizeof(printed[0]), PETSC_COMM_SELF,
             PETSC_ERR_PLIB, "registry_print_help: more modules than it can track");
  for (size_t k = 0; k < N_SCENES; k++)
    if (!strcmp(scene_table[k].name, chosen))
      first = k;
  if (first == N_SCENES) {
    scene *none;
    PetscCall(registry_create_scene(chosen, &none)); /* the error naming the scenes */
  }
  /* the chosen scene first: its values are the ones listed (options_help_freeze) */
  PetscCall(registry_help_scene(s, first, printed));
  snprintf(note, sizeof(note), "not used by scene %s", chosen);
  options_help_freeze(note);
  for (size_t k = 0; k < N_SCENES; k++)
    if (k != first)
      PetscCall(registry_help_scene(s, k, printed));
  /* modules only an option enables (the nonlinear bond: -bond_style nonlinear)
   * get a second pass with that choice made, so -help lists every option */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-bond_style", &user_style));
  if (!user_style) {
    PetscCall(PetscOptionsSetValue(NULL, "-bond_style", "nonlinear"));
    for (size_t k = 0; k < N_SCENES; k++)
      PetscCall(registry_help_scene(s, k, printed));
    PetscCall(PetscOptionsClearValue(NULL, "-bond_style"));
  }
  PetscCall(PetscPrintf(
      s->comm,
      "Options of scene %s with the values this run would use (defaults, the options file and "
      "the command line applied), then those of the other scenes:\n",
      chosen));
  PetscCall(options_help_print(s->comm));
  PetscCall(PetscPrintf(
      s->comm, "\nPETSc's own options (-log_view, -malloc_dump, -options_left, ...) work as "
               "usual and are not listed.\n"));
  PetscFunctionReturn(0);
}
