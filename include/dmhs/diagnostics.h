/* The diagnostics' list (src/diag/diagnostics.c). A scene registers the
 * diagnostics it wants in its build, with the geometry they measure
 * (diagnostics_add); the driver samples the due ones after every step and once
 * before step 1 (step 0), in the order they were registered, each under a
 * PETSc log event of its own name ("Diag:<name>" in -log_view). */
#ifndef DMHS_DIAGNOSTICS_H
#define DMHS_DIAGNOSTICS_H
#include <petscsys.h>
#include "dmhs/diagnostic.h"

struct sim;

/* A zeroed diagnostic named name (letters, digits, '_'). */
PetscErrorCode diagnostic_create(const char *name, diagnostic **out);
/* Appends d to s's list (which then owns it) and registers its log event;
 * refuses a second diagnostic of the same name. */
PetscErrorCode diagnostics_add(struct sim *s, diagnostic *d);
/* The registered diagnostic of that name, or NULL. */
diagnostic *diagnostics_find(const struct sim *s, const char *name);
/* Whether the current step is an output time (step 0 included, and the final output of a run
 * whose last step was not one): sim's output_step, which the driver's schedule sets. */
PetscBool diagnostic_output_time(const struct sim *s);
/* Whether d samples at the current step (its schedule, then its own due). */
PetscBool diagnostic_is_due(const diagnostic *d, const struct sim *s);
/* Samples every due diagnostic, in registration order. Collective. */
PetscErrorCode diagnostics_sample(struct sim *s);
/* The final output of a run whose last step was not an output time (sim's output_step set):
 * samples every at_outputs diagnostic that did not sample at this step. Collective. */
PetscErrorCode diagnostics_sample_final(struct sim *s);
/* Every diagnostic's end-of-run report, in registration order. Collective. */
PetscErrorCode diagnostics_finish(struct sim *s);
/* Destroys and frees every diagnostic; the list is empty after. */
PetscErrorCode diagnostics_destroy(struct sim *s);

#endif
