/* A minimal hand-assembled sim for the solid modules' unit tests: no scene,
 * closed or periodic box, modules enabled by registry name. */
#ifndef DMHS_TEST_SOLID_FIXTURE_H
#define DMHS_TEST_SOLID_FIXTURE_H
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <string.h>
#include <cmocka.h>
#include "dmhs/sim.h"
#include "dmhs/neighbours.h"
#include "dmhs/modules.h"
#include "dmhs/run.h"
#include "dmhs/registry.h"
#include "dmhs/events.h"
#include "dmhs/integrate.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/substep.h"
#include "dmhs/solid_modes.h"
#include "dmhs/fields.h"

#define OK(call) assert_int_equal((call), 0)

static inline sim *fixture_create(double lx, double ly, PetscBool periodic_x) {
  sim *s;
  OK(registry_initialize());
  OK(PetscNew(&s));
  s->comm = PETSC_COMM_SELF;
  s->size = 1;
  s->t_end = 1;
  OK(particles_create(&s->ps));
  OK(cells_create(&s->cel));
  s->dom.lo[0] = s->dom.lo[1] = 0;
  s->dom.hi[0] = lx;
  s->dom.hi[1] = ly;
  s->dom.periodic[0] = periodic_x;
  OK(topology_create(&s->topo));
  return s;
}

/* After particles and structure are in: options pass, ghosts, setup, forces at t = 0. */
static inline void fixture_setup(sim *s) {
  double reach = 0;
  for (int m = 0; m < s->n_modules; m++)
    OK(s->modules[m]->set_from_options(s->modules[m], s));
  for (int m = 0; m < s->n_modules; m++) {
    reach = PetscMax(reach, s->modules[m]->reach);
    if (s->modules[m]->needs & MODULE_NEEDS_PAIRS)
      s->pair_cutoff = PetscMax(s->pair_cutoff, s->modules[m]->reach);
  }
  OK(halo_create(&s->hal, reach, PETSC_COMM_SELF));
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->setup)
      OK(s->modules[m]->setup(s->modules[m], s));
  OK(neighbours_rebuild(s));
  OK(sim_compute_forces(s));
}

static inline double fixture_energy(sim *s, double P[2]) {
  double e = 0, pe;
  P[0] = P[1] = 0;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    if (s->ps.type[i] == PTYPE_WALL)
      continue;
    e += 0.5 * s->ps.mass[i] * (s->ps.v[i][0] * s->ps.v[i][0] + s->ps.v[i][1] * s->ps.v[i][1]);
    P[0] += s->ps.mass[i] * s->ps.v[i][0];
    P[1] += s->ps.mass[i] * s->ps.v[i][1];
  }
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->energy) {
      OK(s->modules[m]->energy(s->modules[m], s, &pe));
      e += pe;
    }
  return e;
}

/* -solid_substeps n (before any particle is added): the held acceleration's field */
static inline void fixture_substeps(sim *s, PetscInt n) {
  s->substeps.n = n;
  s->substeps.on = n != 1 ? PETSC_TRUE : PETSC_FALSE;
  s->substeps.mode_factor = SOLID_MODES_LIMIT;
  fields_reset();
  if (s->substeps.on) {
    OK(fields_enable("a_hold"));
    OK(fields_enable("substepped"));
  }
}

/* One step as run_steps takes it (fixed dt, no migration). */
static inline void fixture_step(sim *s) {
  if (s->substeps.on)
    OK(substep_mark_members(s));
  OK(integrate_first_half(s));
  if (s->substeps.on)
    OK(substep_solids(s));
  s->step++;
  s->t = s->step * s->dt;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    domain_wrap(&s->dom, s->ps.x[i]);
  OK(neighbours_rebuild(s));
  OK(sim_compute_forces(s));
  OK(integrate_second_half(s));
}

static inline void fixture_destroy(sim **s) {
  OK(sim_destroy(s));
}

/* deterministic uniform numbers in [-1, 1) */
static inline double fixture_rand(unsigned long long *state) {
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*state >> 11) / 4503599627370496.0 - 1.0;
}

#endif
