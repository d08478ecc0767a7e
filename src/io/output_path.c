/* Where the run's files go: <output_dir>/<name>. */
#include "dmhs/sim.h"
#include "dmhs/io.h"

PetscErrorCode io_output_path(const sim *s, const char *name, char *path, size_t len) {
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, len, "%s/%s", s->io->output_dir, name));
  PetscFunctionReturn(0);
}
