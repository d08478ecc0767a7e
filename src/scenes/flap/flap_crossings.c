/* The diagnostic "flap_crossings": no liquid may pass through the flap
 * (flap_metrics.h). */
#include <math.h>
#include "dmhs/checkpoint.h"
#include "dmhs/diagnostics.h"
#include "flap_strip.h"

typedef struct {
  flap_strip st;
  signed char *side; /* per fluid gid: -1/+1 beside the flap, 0 = not beside */
  PetscInt crossings;
} flap_crossings;

static PetscErrorCode flap_crossings_sample(diagnostic *self, sim *s) {
  flap_crossings *f = self->data;
  const particles *ps = &s->ps;
  const PetscInt n_fluid = f->st.lay.n_fluid;
  signed char *now_all;
  PetscFunctionBeginUser;
  PetscCall(flap_strip_gather(&f->st, s));
  /* mpi: each owner sets its particles' side, one Allreduce makes the whole
   * list; every rank then counts the same crossings */
  PetscCall(PetscCalloc1(n_fluid, &now_all));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->gid[i] >= n_fluid)
      continue;
    const double xm = flap_strip_midline_x(&f->st, ps->x[i][1]);
    signed char now = 0;
    if (!isnan(xm)) {
      double d[2] = {ps->x[i][0] - xm, 0};
      domain_min_image(&s->dom, d);
      if (fabs(d[0]) < 3 * f->st.lay.dx)
        now = d[0] < 0 ? -1 : 1;
    }
    now_all[ps->gid[i]] = now;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, now_all, (PetscMPIInt)n_fluid, MPI_SIGNED_CHAR, MPI_SUM,
                             s->comm));
  for (PetscInt g = 0; g < n_fluid; g++) {
    if (f->side[g] && now_all[g] && f->side[g] != now_all[g])
      f->crossings++;
    f->side[g] = now_all[g];
  }
  PetscCall(PetscFree(now_all));
  PetscFunctionReturn(0);
}

/* The count and the side of every fluid gid (a particle that changes side
 * between the checkpoint and the next check must count as it would have
 * without the restart). Replicated on every rank. */
static PetscErrorCode flap_crossings_checkpoint_write(diagnostic *self, sim *s, checkpoint_io *io) {
  flap_crossings *f = self->data;
  const PetscInt n_fluid = f->st.lay.n_fluid;
  const PetscInt64 crossings = f->crossings;
  PetscInt64 *side;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscMalloc1(n_fluid + 1, &side));
  for (PetscInt g = 0; g < n_fluid; g++)
    side[g] = f->side[g];
  PetscCall(checkpoint_put_ints(io, "flap_crossings", &crossings, 1));
  PetscCall(checkpoint_put_ints(io, "flap_side", side, n_fluid));
  PetscCall(PetscFree(side));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_crossings_checkpoint_read(diagnostic *self, sim *s, checkpoint_io *io) {
  flap_crossings *f = self->data;
  const PetscInt n_fluid = f->st.lay.n_fluid;
  PetscInt64 crossings, *side;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(PetscMalloc1(n_fluid + 1, &side));
  PetscCall(checkpoint_get_ints(io, "flap_crossings", &crossings, 1));
  PetscCall(checkpoint_get_ints(io, "flap_side", side, n_fluid));
  f->crossings = (PetscInt)crossings;
  for (PetscInt g = 0; g < n_fluid; g++)
    f->side[g] = (signed char)side[g];
  PetscCall(PetscFree(side));
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_crossings_destroy(diagnostic *self) {
  flap_crossings *f = self->data;
  PetscFunctionBeginUser;
  PetscCall(flap_strip_destroy(&f->st));
  PetscCall(PetscFree(f->side));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscInt flap_crossings_count(const diagnostic *crossings) {
  return ((const flap_crossings *)crossings->data)->crossings;
}

PetscErrorCode flap_crossings_register(sim *s, const flap_layout *lay, PetscInt interval,
                                       diagnostic **out) {
  diagnostic *d;
  flap_crossings *f;
  PetscFunctionBeginUser;
  PetscCheck(interval >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "flap: the crossing check interval must be >= 1 step (got %" PetscInt_FMT ")",
             interval);
  PetscCall(diagnostic_create("flap_crossings", &d));
  PetscCall(PetscNew(&f));
  d->data = f;
  PetscCall(flap_strip_create(lay, &f->st));
  PetscCall(PetscCalloc1(lay->n_fluid, &f->side));
  d->when.every_steps = interval;
  d->when.at_outputs = PETSC_TRUE; /* the rows of "flap" report an up-to-date count */
  d->sample = flap_crossings_sample;
  d->destroy = flap_crossings_destroy;
  d->checkpoint_write = flap_crossings_checkpoint_write;
  d->checkpoint_read = flap_crossings_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  *out = d;
  PetscFunctionReturn(0);
}
