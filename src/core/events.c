/* Every PetscLogEvent and stage of dmhs, registered in one place, so that
 * -log_view shows where the time of each module went. */
#include "dmhs/events.h"

dmhs_events events;

PetscErrorCode events_register(void) {
  PetscClassId id;
  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("dmhs", &id));
  PetscCall(PetscLogStageRegister("dmhs setup", &events.stage_setup));
  PetscCall(PetscLogStageRegister("dmhs steps", &events.stage_steps));
  PetscCall(PetscLogEventRegister("Integrate", id, &events.integrate));
  PetscCall(PetscLogEventRegister("SolidSubsteps", id, &events.substeps));
  PetscCall(PetscLogEventRegister("TimeStep", id, &events.timestep));
  PetscCall(PetscLogEventRegister("Migrate", id, &events.migrate));
  PetscCall(PetscLogEventRegister("HaloBuild", id, &events.halo_build));
  PetscCall(PetscLogEventRegister("HaloForward", id, &events.halo_forward));
  PetscCall(PetscLogEventRegister("PairList", id, &events.pairs));
  PetscCall(PetscLogEventRegister("SphDensity", id, &events.sph_density));
  PetscCall(PetscLogEventRegister("SphEos", id, &events.sph_eos));
  PetscCall(PetscLogEventRegister("SphWall", id, &events.sph_wall));
  PetscCall(PetscLogEventRegister("SphCorrection", id, &events.sph_correction));
  PetscCall(PetscLogEventRegister("SphForce", id, &events.sph_force));
  PetscCall(PetscLogEventRegister("SphTensile", id, &events.sph_tensile));
  PetscCall(PetscLogEventRegister("BodyForce", id, &events.body_force));
  PetscCall(PetscLogEventRegister("Diagnostics", id, &events.diagnostics));
  PetscCall(PetscLogEventRegister("Output", id, &events.output));
  PetscCall(PetscLogEventRegister("CheckState", id, &events.check_state));
  PetscCall(PetscLogEventRegister("Partition", id, &events.partition));
  PetscCall(PetscLogEventRegister("HaloExchange", id, &events.halo_exchange));
  PetscCall(PetscLogEventRegister("Checkpoint", id, &events.checkpoint));
  /* solids */
  PetscCall(PetscLogEventRegister("Topology", id, &events.topology));
  PetscCall(PetscLogEventRegister("Bond", id, &events.bond));
  PetscCall(PetscLogEventRegister("Angle", id, &events.angle));
  PetscCall(PetscLogEventRegister("Repulsion", id, &events.repulsion));
  PetscCall(PetscLogEventRegister("SolidLoad", id, &events.solid_load));
  PetscCall(PetscLogEventRegister("Peristalsis", id, &events.peristalsis));
  PetscFunctionReturn(0);
}
