/* The physics-module interface: a small struct of functions a scene enables.
 * Dispatch happens once per sweep, never per pair. */
#ifndef DMHS_MODULE_H
#define DMHS_MODULE_H
#include <petscsys.h>
#include <petscviewer.h>

struct sim;
struct dt_limits;
struct checkpoint_io;
struct solid_jacobian;

/* MODULE_NEEDS_PAIRS: neighbours within the module's reach (sets the cutoff of the cells);
 * MODULE_CELLS_ONLY, set by the module's setup: it walks the cells itself and reads no pair
 * list, so a run whose every pair module says so builds none (memory, time).
 * What a module asks the integrator to advance besides x and v, set by its options pass:
 * MODULE_INTEGRATES_DENSITY: its compute adds density rates drho (continuity), and rho
 * follows them; MODULE_PREDICTS_DENSITY: its forces want to see rho^n + dt drho^n,
 * corrected to the trapezoid after them (integrate.c), not the half-step density.
 * MODULE_SETS_RATES, set by the module's setup: its compute sets a and drho of every owned
 * row instead of adding to them when it is the first module of a force evaluation (it reads
 * sim's rates_unset), so that evaluation need not zero them first (sim.c). */
enum {
  MODULE_NEEDS_PAIRS = 1u << 0,
  MODULE_NEEDS_BONDS = 1u << 1,
  MODULE_NEEDS_ANGLES = 1u << 2,
  MODULE_CELLS_ONLY = 1u << 3,
  MODULE_INTEGRATES_DENSITY = 1u << 4,
  MODULE_PREDICTS_DENSITY = 1u << 5,
  MODULE_SETS_RATES = 1u << 6
};

typedef struct module module;
struct module {
  const char *name;
  unsigned needs;
  /* Its forces depend on positions only and are evaluated on every solid
   * sub-step with -solid_substeps (bonds, angles; the repulsion with
   * -repulsion_substeps), and its time-step limits bound the sub-step. */
  PetscBool solid_internal;
  /* Optional, for a solid_internal module whose forces reach beyond the solids
   * (the repulsion's liquid in contact): sets mark[i] = 1 on the owned rows
   * that must move on this step's sub-steps with the solids, from the state at
   * the start of the step. Called before the step's first kick. */
  PetscErrorCode (*substep_members)(module *self, struct sim *s, PetscInt *mark);
  /* Optional, for a solid_internal module: adds the 2x2 blocks -dF_p/dx_q of its forces'
   * Jacobian at the current positions, for every pair of rows (p, q) of each interaction
   * (p = q too), with solid_jacobian_add. With sub-steps they bound the solids' fastest
   * mode, which dt itself must resolve (solid_modes.h). */
  PetscErrorCode (*jacobian_blocks)(module *self, struct sim *s, struct solid_jacobian *J);
  double reach; /* longest interaction distance [m]; sets the ghost width */
  /* NULL-terminated names of the ghost fields its sweeps read on ghost rows (beyond the
   * FIELD_FIXED ones, which ghosts keep from their build): between builds a step refreshes
   * the union of these, once, before the force evaluation. A field a module recomputes on
   * ghost rows itself (SPH's p, v_visc) is not listed. NULL = reads no ghost row. */
  const char *const *ghost_reads;
  PetscErrorCode (*set_from_options)(module *self, struct sim *s);
  PetscErrorCode (*setup)(module *self, struct sim *s);
  /* A force evaluation has two phases (sim_add_module_forces). Optional phase one,
   * prepare: evaluates what other modules read during theirs at this evaluation's time
   * (the body force's value, which the wall pass needs); runs for every module before any
   * compute. Phase two, compute: one whole sweep that adds accelerations / density rates of
   * owned particles, in the order the modules were enabled. */
  PetscErrorCode (*prepare)(module *self, struct sim *s);
  PetscErrorCode (*compute)(module *self, struct sim *s);
  /* Appends this module's time-step limits. */
  PetscErrorCode (*max_dt)(module *self, struct sim *s, struct dt_limits *limits);
  PetscErrorCode (*view)(module *self, struct sim *s, PetscViewer viewer);
  /* Optional: checks of its own beyond the time-step limits, one line each under the
   * stability report; adds the number of problems found (each stops a run, or warns with
   * -preflight warn). */
  PetscErrorCode (*preflight)(module *self, struct sim *s, int *problems);
  PetscErrorCode (*destroy)(module *self);
  void *data;
  /* Optional: save / restore private state a restart needs (random-number
   * state, schedules ...) with checkpoint_put_* / checkpoint_get_* (checkpoint.h). */
  PetscErrorCode (*checkpoint_write)(module *self, struct sim *s, struct checkpoint_io *io);
  PetscErrorCode (*checkpoint_read)(module *self, struct sim *s, struct checkpoint_io *io);
  /* Potential energy of this module's interactions [J], summed over ranks
   * (NULL when the module has none, e.g. SPH or body forces). */
  PetscErrorCode (*energy)(module *self, struct sim *s, double *e);
  /* Optional (stress diagnostics, src/diag/stress.c): adds this module's
   * per-particle virial W_i = -1/2 sum_j (x_i - x_j) (x) F_ij, components
   * (xx, xy, yy) [N m per unit depth], to W[i] for the rows its forces reach,
   * exactly as compute() distributes forces (writes to ghost rows are ignored). */
  PetscErrorCode (*virial)(module *self, struct sim *s, double (*W)[3]);
  /* Optional: runs at the end of every step, after the state check and
   * before the scene's diagnostics. It may change the structure: bonds and
   * angles through the collective topology_add_bonds / topology_remove_bonds,
   * which mark the topology changed, or particle types, after which it sets
   * sim->force_rebuild (and checkpoints that flag). Either way the next step
   * migrates and rebuilds ghosts, pairs and the topology's resolution before
   * its force sweep (a rebuild here would leave migrated rows without their
   * derived fields, e.g. p, until then). Collective. */
  PetscErrorCode (*post_step)(module *self, struct sim *s);
};

#endif
