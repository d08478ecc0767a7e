/* What rank 0 tells the user while a run goes: a status line at an interval
 * and the one-line summary at the end. */
#ifndef DMHS_PROGRESS_H
#define DMHS_PROGRESS_H
#include <petscsys.h>

struct sim;
/* Status line: step, t, dt, particle-steps/s, ETA, max |v|, max density deviation. */
PetscErrorCode progress_print(struct sim *s);
/* Final line, always printed (also with -quiet): includes "particle-steps/s: <value>". */
PetscErrorCode progress_summary(struct sim *s);

#endif
