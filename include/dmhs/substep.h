/* Solid sub-cycling (-solid_substeps N, N != 1), the scheme SPHinXsys uses
 * for fluid-structure interaction (Zhang, Rezavand & Hu, J. Comput. Phys.
 * 2021): the liquid takes one step of dt; the solids take N velocity-Verlet
 * sub-steps of dt/N in which only their own bonds and angles (the
 * solid_internal modules) are evaluated again, and every other force on them
 * (liquid pressure and viscosity, repulsion, loads, peristalsis, damping) is
 * held at its value from the force evaluation at the start of the step
 * (a_hold). The liquid sees the solids' velocity predicted for the end of the
 * step (v_est), as it sees its own; with N = 1 the step is the plain one.
 * With -repulsion_substeps the solid-liquid and solid-wall contact is a
 * sub-cycled force too, and the liquid particles in contact move on the
 * sub-steps with the solids (multi-rate): the stiff contact then bounds the
 * sub-step instead of the liquid's step. */
#ifndef DMHS_SUBSTEP_H
#define DMHS_SUBSTEP_H
#include <petscsys.h>

struct sim;

/* -solid_substeps 0 picks at most this many */
#define SUBSTEPS_MAX 1000

/* The solids' sub-steps of the current step, which the driver's time-step control
 * (timestep.h) sets before it. */
typedef struct substep_plan {
  PetscBool on; /* sub-cycling: -solid_substeps other than 1 */
  PetscInt n;   /* sub-steps of the current step */
  /* -solid_substeps_scheme: how the forces that are not sub-cycled act on the rows that move
   * on the sub-steps: half at each end of the step (r-RESPA) or held at their start-of-step
   * value on every sub-step */
  PetscBool respa;
  double mode_factor; /* -solid_mode_dt_factor: dt <= mode_factor/omega (solid_modes.h) */
} substep_plan;

/* Before the step's first kick: marks the rows that move on its sub-steps
 * (particles.substepped): the solids, and what the sub-cycled modules add
 * (module.substep_members). */
PetscErrorCode substep_mark_members(struct sim *s);
/* After the liquid's first kick and drift: the marked rows' N sub-steps. */
PetscErrorCode substep_solids(struct sim *s);
/* The force evaluation when sub-cycling: the solid_internal modules first,
 * whose share of the solids' acceleration is kept apart, then the others;
 * a_hold = a - that share. */
PetscErrorCode substep_compute_forces(struct sim *s);

#endif
