/* Checkpoints (src/io/checkpoint.c): the whole state needed to continue a run
 * bitwise, in one HDF5 file written collectively and atomically (<file>.tmp,
 * then rename: a failed write leaves the previous checkpoint intact).
 *   attributes of /:   magic "DMHS-CHECKPOINT", format_version, dmhs_version,
 *                      scene, options, physics_options (every physics option's
 *                      value, "name value" lines: options_physics), n_ranks,
 *                      n_particles, step, t, dt,
 *                      next_output_t, next_progress_t (the driver's, io_checkpoint_keep_real),
 *                      snapshot_index,
 *                      diagnostics_sampled (per registered diagnostic, 1 if it
 *                      sampled at this step; absent in older files: all)
 *   /particles/<field> every FIELD_CHECKPOINT field at its native width
 *   /particles/rank_counts  owned particles per rank when written
 *   /topology/         the bond/angle store (scenes with bonds): bond_gid (n x 2),
 *                      bond_type, bond_r0, bond_id, angle_gid (n x 3), angle_type,
 *                      angle_id, each entry once (rows of the rank owning its first
 *                      end); attributes next_bond_id, next_angle_id
 *   /modules/<name>/   private state of modules with checkpoint hooks
 *   /diagnostics/<name>/  private state of diagnostics with checkpoint hooks
 *                      (counters, histories, error reports done)
 * Module and diagnostic state is replicated (the same on every rank): hooks store
 * named arrays with checkpoint_put_* and read them back with checkpoint_get_*.
 * Every dataset has an attribute "checksum" (uint64 stored as int64): the sum
 * modulo 2^64 over its rows of FNV-1a 64 of (global row index as 8 bytes little
 * endian, row bytes), the same whatever the rank split; reading verifies it
 * and that no gid appears twice, and refuses the file naming the dataset. */
#ifndef DMHS_CHECKPOINT_H
#define DMHS_CHECKPOINT_H
#include <petscsys.h>

struct sim;

#define CHECKPOINT_MAGIC "DMHS-CHECKPOINT"
/* 2: x_build (neighbour lists with a skin); 3: physics_options, per-dataset checksums;
 * 4: dt_anchor_t, dt_anchor_step, solid_substeps (dt and the sub-steps change during the run);
 * 5: the tag split into load / segment / tracer;
 * 6: /diagnostics/<name>/, one group per diagnostic, instead of the scene's /scene/;
 * 7: /topology (the bond/angle store; the clot bonds leave the agglomeration module's state) */
#define CHECKPOINT_FORMAT_VERSION 7

/* Opaque handle given to the modules' and diagnostics' checkpoint hooks. */
typedef struct checkpoint_io checkpoint_io;

PetscErrorCode checkpoint_put_reals(checkpoint_io *io, const char *name, const double *v,
                                    PetscInt n);
PetscErrorCode checkpoint_put_ints(checkpoint_io *io, const char *name, const PetscInt64 *v,
                                   PetscInt n);
/* n must match what was stored; checkpoint_get_length tells it (-1 = absent). */
PetscErrorCode checkpoint_get_length(checkpoint_io *io, const char *name, PetscInt *n);
PetscErrorCode checkpoint_get_reals(checkpoint_io *io, const char *name, double *v, PetscInt n);
PetscErrorCode checkpoint_get_ints(checkpoint_io *io, const char *name, PetscInt64 *v, PetscInt n);

/* Writes the current state to path atomically. Collective. */
PetscErrorCode checkpoint_write(struct sim *s, const char *path);
/* Replaces the particle state, run control and module / diagnostic state by path's.
 * The scene must already be built with the same options (same particle count).
 * Ghosts are dropped; the caller rebuilds them. Collective. */
PetscErrorCode checkpoint_read(struct sim *s, const char *path);

#endif
