/* The diagnostic interface: an object that measures the state after the steps
 * of its own schedule and owns its output file, its end-of-run report and the
 * state a restart needs. Like the module interface (module.h) it sits below
 * every layer that calls it: the checkpoint (io) stores what its hooks give.
 * The list that registers, schedules and samples them is the diag layer's
 * (diagnostics.h). */
#ifndef DMHS_DIAGNOSTIC_H
#define DMHS_DIAGNOSTIC_H
#include <petscsys.h>

struct sim;
struct checkpoint_io;

/* When a diagnostic samples: at a step that any of the set conditions selects.
 * Output times are those of the snapshots (-output_interval): step 0 and every
 * step with t within dt/2 of the next output time. */
typedef struct diagnostic_schedule {
  PetscInt every_steps;   /* > 0: at the steps that are multiples of it, step 0 included */
  PetscBool at_outputs;   /* at the output times */
  PetscBool not_at_start; /* never at step 0 (a row there would say nothing) */
} diagnostic_schedule;

typedef struct diagnostic diagnostic;
struct diagnostic {
  char name[64];      /* its log event and its checkpoint group (/diagnostics/<name>) */
  const char *output; /* the file it owns in -output_dir, NULL when it only reports */
  diagnostic_schedule when;
  /* Optional: instants of its own besides the schedule (the errors' report times). */
  PetscBool (*due)(const diagnostic *self, const struct sim *s);
  /* Measures the current state; called on every rank (collective). */
  PetscErrorCode (*sample)(diagnostic *self, struct sim *s);
  /* Optional: the end-of-run report (after the last step). Collective. */
  PetscErrorCode (*finish)(diagnostic *self, struct sim *s);
  /* Optional: frees data and closes files (the struct itself is freed by the list). */
  PetscErrorCode (*destroy)(diagnostic *self);
  /* Optional: save / restore what an exact restart needs (counters, histories,
   * reports done) with checkpoint_put_* / checkpoint_get_* (checkpoint.h). */
  PetscErrorCode (*checkpoint_write)(diagnostic *self, struct sim *s, struct checkpoint_io *io);
  PetscErrorCode (*checkpoint_read)(diagnostic *self, struct sim *s, struct checkpoint_io *io);
  void *data;
  PetscLogEvent event; /* set by diagnostics_add */
  /* Kept by the list: the step of its last sample (-1: none yet), and after a restart
   * whether it had sampled at the checkpoint's step, so that its files keep their rows
   * at that time (csv.c; errors.c by step) only then. */
  PetscInt sampled_step;
  PetscBool restart_sampled;
};

#define SIM_MAX_DIAGNOSTICS 16

#endif
