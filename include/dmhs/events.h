/* Every PetscLogEvent and stage of dmhs, registered in one place. */
#ifndef DMHS_EVENTS_H
#define DMHS_EVENTS_H
#include <petsclog.h>

typedef struct dmhs_events {
  PetscLogStage stage_setup, stage_steps;
  PetscLogEvent integrate, migrate, halo_build, halo_forward, pairs;
  PetscLogEvent sph_density, sph_eos, sph_wall, sph_correction, sph_force, sph_tensile, body_force;
  PetscLogEvent diagnostics, output, check_state;
  PetscLogEvent partition, halo_exchange; /* mpi: METIS; the MPI part of halo build/forward */
  PetscLogEvent checkpoint;
  PetscLogEvent topology, bond, angle, repulsion, solid_load; /* solids */
  PetscLogEvent peristalsis;                                  /* intestine */
  PetscLogEvent substeps, timestep; /* solid sub-steps; the limits before every step */
} dmhs_events;

extern dmhs_events events;
PetscErrorCode events_register(void);

#endif
