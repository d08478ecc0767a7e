/* The physics modules by name: the one table a new module is registered in, and how a
 * scene enables one (modules_enable), so that -help can list every module's options and a
 * scene names what it needs. */
#include <string.h>
#include "dmhs/modules.h"
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/body_force.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/solid_load.h"
#include "dmhs/peristalsis.h"
#include "dmhs/agglomeration.h"
#include "dmhs/wall_wave.h"

static const struct {
  const char *name;
  PetscErrorCode (*create)(module **);
} module_table[] = {
    {"sph", sph_module_create},
    {"body_force", body_force_module_create},
    /* solids */
    {"bond_harmonic", bond_harmonic_module_create},
    {"bond_nonlinear", bond_nonlinear_module_create},
    {"angle_harmonic", angle_harmonic_module_create},
    {"repulsion", repulsion_module_create},
    {"solid_load", solid_load_module_create},
    {"peristalsis", peristalsis_module_create},     /* intestine */
    {"agglomeration", agglomeration_module_create}, /* vein clots */
    {"wall_wave", wall_wave_module_create},         /* peristaltic channel */
};

#define N_MODULES (sizeof(module_table) / sizeof(module_table[0]))

size_t modules_count(void) {
  return N_MODULES;
}

const char *modules_name(size_t k) {
  return k < N_MODULES ? module_table[k].name : NULL;
}

PetscErrorCode modules_create(const char *name, module **out) {
  PetscFunctionBeginUser;
  for (size_t k = 0; k < N_MODULES; k++)
    if (!strcmp(module_table[k].name, name)) {
      PetscCall(module_table[k].create(out));
      PetscFunctionReturn(0);
    }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "unknown physics module '%s'", name);
}

PetscErrorCode modules_enable(sim *s, const char *name, module **out) {
  PetscFunctionBeginUser;
  PetscCheck(s->n_modules < SIM_MAX_MODULES, s->comm, PETSC_ERR_PLIB, "too many modules");
  for (int m = 0; m < s->n_modules; m++)
    PetscCheck(strcmp(s->modules[m]->name, name), s->comm, PETSC_ERR_PLIB,
               "module %s enabled twice", name);
  PetscCall(modules_create(name, &s->modules[s->n_modules]));
  /* a module that asks for bonds or angles gets the store */
  if ((s->modules[s->n_modules]->needs & (MODULE_NEEDS_BONDS | MODULE_NEEDS_ANGLES)) && !s->topo)
    PetscCall(topology_create(&s->topo));
  if (out)
    *out = s->modules[s->n_modules];
  s->n_modules++;
  PetscFunctionReturn(0);
}
