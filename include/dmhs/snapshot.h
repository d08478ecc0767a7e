/* Particle snapshots (src/io/snapshot.c): <output_dir>/snap_<NNNNNN>.h5, one
 * file per output time, written collectively by all ranks (each its owned rows,
 * in rank order). Contents:
 *   /particles/<field>  every FIELD_OUTPUT field of the field table; scalars as
 *                       N datasets, 2D vectors as N x 3 with z = 0 (ParaView
 *                       treats only 3-component arrays as vectors)
 *   attributes of /:    time [s], step, dt [s], dim (2), n_particles,
 *                       dmhs_version, scene, options (the resolved options),
 *                       box_lo, box_hi [m] and periodic (0/1) per dimension, dx [m]
 *                       (the rest spacing), and the modules' own (io.h: with SPH,
 *                       sph_kernel and sph_h [m])
 * Written to <name>.tmp and renamed once complete. */
#ifndef DMHS_SNAPSHOT_H
#define DMHS_SNAPSHOT_H
#include <petscsys.h>
#include "dmhs/fields.h"

struct sim;

/* Components a field has in a snapshot file (2D vectors are padded to 3). */
int snapshot_file_width(const field_desc *f);
/* File name (no directory) of snapshot number index. */
PetscErrorCode snapshot_name(PetscInt index, char *name, size_t len);
/* Writes snapshot number index of the current state; returns the particle count. */
PetscErrorCode snapshot_write(struct sim *s, PetscInt index, PetscInt64 *n_global,
                              PetscInt64 *n_bonds);

#endif
