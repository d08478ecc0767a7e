/* The list of diagnostics of a run (diagnostics.h): registration, schedule,
 * sampling under per-diagnostic log events, end-of-run reports, teardown.
 * Their checkpoint groups are written and read by src/io/checkpoint.c. */
#include <ctype.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/diagnostics.h"
#include "dmhs/events.h"

PetscErrorCode diagnostic_create(const char *name, diagnostic **out) {
  size_t len;
  PetscFunctionBeginUser;
  PetscCall(PetscStrlen(name, &len));
  PetscCheck(len > 0 && len < sizeof((*out)->name), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "diagnostic name '%s': 1 to %zu characters", name, sizeof((*out)->name) - 1);
  /* the name becomes an HDF5 group in checkpoints: nothing that would nest or escape */
  for (size_t k = 0; k < len; k++)
    PetscCheck(isalnum((unsigned char)name[k]) || name[k] == '_', PETSC_COMM_SELF,
               PETSC_ERR_ARG_WRONG, "diagnostic name '%s': only letters, digits and '_'", name);
  PetscCall(PetscNew(out));
  PetscCall(PetscStrncpy((*out)->name, name, sizeof((*out)->name)));
  (*out)->sampled_step = -1;
  (*out)->restart_sampled = PETSC_TRUE;
  PetscFunctionReturn(0);
}

diagnostic *diagnostics_find(const sim *s, const char *name) {
  for (int k = 0; k < s->n_diagnostics; k++)
    if (!strcmp(s->diagnostics[k]->name, name))
      return s->diagnostics[k];
  return NULL;
}

PetscErrorCode diagnostics_add(sim *s, diagnostic *d) {
  static PetscClassId id = 0;
  char event[80];
  PetscFunctionBeginUser;
  PetscCheck(d->sample, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "diagnostic %s has no sample",
             d->name);
  PetscCheck(!diagnostics_find(s, d->name), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "diagnostic %s registered twice", d->name);
  PetscCheck(s->n_diagnostics < SIM_MAX_DIAGNOSTICS, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "more than %d diagnostics", SIM_MAX_DIAGNOSTICS);
  PetscCheck(d->when.every_steps >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "diagnostic %s: every_steps %" PetscInt_FMT " < 0", d->name, d->when.every_steps);
  /* PETSc returns the event already registered under a name: one per name, whatever
   * the number of runs in the process (the unit tests) */
  PetscCall(PetscSNPrintf(event, sizeof(event), "Diag:%s", d->name));
  if (!id)
    PetscCall(PetscClassIdRegister("dmhs diagnostic", &id));
  PetscCall(PetscLogEventRegister(event, id, &d->event));
  s->diagnostics[s->n_diagnostics++] = d;
  PetscFunctionReturn(0);
}

PetscBool diagnostic_output_time(const sim *s) {
  return s->output_step;
}

PetscBool diagnostic_is_due(const diagnostic *d, const sim *s) {
  const diagnostic_schedule *w = &d->when;
  if (!(s->step == 0 && w->not_at_start)) {
    if (w->every_steps > 0 && s->step % w->every_steps == 0)
      return PETSC_TRUE;
    if (w->at_outputs && diagnostic_output_time(s))
      return PETSC_TRUE;
  }
  return d->due ? d->due(d, s) : PETSC_FALSE;
}

/* One sample under its log event; csv_open, if it opens a file now, learns whether the rows at
 * the restart's time are this diagnostic's (io_state.csv_keep_restart_rows). */
static PetscErrorCode diagnostic_sample_one(diagnostic *d, sim *s) {
  PetscFunctionBeginUser;
  s->io->csv_keep_restart_rows = d->restart_sampled;
  PetscCall(PetscLogEventBegin(d->event, 0, 0, 0, 0));
  PetscCall(d->sample(d, s));
  PetscCall(PetscLogEventEnd(d->event, 0, 0, 0, 0));
  s->io->csv_keep_restart_rows = PETSC_TRUE;
  d->sampled_step = s->step;
  PetscFunctionReturn(0);
}

PetscErrorCode diagnostics_sample(sim *s) {
  PetscFunctionBeginUser;
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    if (diagnostic_is_due(d, s))
      PetscCall(diagnostic_sample_one(d, s));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode diagnostics_sample_final(sim *s) {
  PetscFunctionBeginUser;
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    if (d->when.at_outputs && d->sampled_step != s->step)
      PetscCall(diagnostic_sample_one(d, s));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode diagnostics_finish(sim *s) {
  PetscFunctionBeginUser;
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    if (d->finish)
      PetscCall(d->finish(d, s));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode diagnostics_destroy(sim *s) {
  PetscFunctionBeginUser;
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    if (d->destroy)
      PetscCall(d->destroy(d));
    PetscCall(PetscFree(s->diagnostics[k]));
  }
  s->n_diagnostics = 0;
  PetscFunctionReturn(0);
}
