/* The driver's output schedule: when a step's state is an output, and its number. */
#include "dmhs/sim.h"
#include "dmhs/run_control.h"

PetscBool run_control_output_due(const run_control *rc, const sim *s) {
  return s->t >= rc->next_output_t - 0.5 * s->dt ? PETSC_TRUE : PETSC_FALSE;
}

PetscInt64 run_control_output_number(const run_control *rc, const sim *s) {
  return (PetscInt64)PetscFloorReal(s->t / rc->output_interval + 0.5);
}

PetscBool run_control_at_end(const sim *s) {
  return s->t >= s->t_end - 0.5 * s->dt ? PETSC_TRUE : PETSC_FALSE;
}
