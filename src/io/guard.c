/* The last guard before a snapshot or checkpoint is written: see guard.h. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "guard.h"

PetscErrorCode io_guard_finite(const sim *s, unsigned flags, const char *path) {
  const particles *ps = &s->ps;
  size_t nf;
  const field_desc *t = fields_table(&nf);
  PetscFunctionBeginUser;
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & flags) || t[k].kind != FIELD_REAL)
      continue;
    const double *v = *fields_member((void *)ps, &t[k]);
    const PetscInt w = t[k].width;
    for (PetscInt i = 0; i < ps->n_owned; i++)
      for (PetscInt c = 0; c < w; c++)
        PetscCheck(isfinite(v[w * i + c]), PETSC_COMM_SELF, PETSC_ERR_FP,
                   "refusing to write %s: particle gid %" PetscInt64_FMT
                   " has a non-finite %s[%d] (%g) "
                   "at step %" PetscInt_FMT ", t = %g s",
                   path, ps->gid[i], t[k].name, (int)c, v[w * i + c], s->step, s->t);
  }
  PetscFunctionReturn(0);
}
