/* Scene flap: placeholder until the coupled case lands. */
#include "dmhs/sim.h"
#include "dmhs/scenes.h"

PetscErrorCode flap_scene_create(scene **out) {
  PetscFunctionBeginUser;
  *out = NULL;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "scene flap: not implemented yet");
}
