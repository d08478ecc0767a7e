/* Inside io: the checkpoint's bond/angle store (topology_checkpoint.c), read and written
 * by checkpoint.c. */
#ifndef DMHS_IO_TOPOLOGY_CHECKPOINT_H
#define DMHS_IO_TOPOLOGY_CHECKPOINT_H
#include <hdf5.h>
#include <petscsys.h>

struct sim;

/* The bond/angle store as the group /topology of the open file fid. Collective. */
PetscErrorCode topology_checkpoint_write(struct sim *s, const char *path, hid_t fid);
/* Replaces the store with the file's: every rank reads it whole and keeps the entries
 * with an end it owns now (migration then takes them where their particles go). */
PetscErrorCode topology_checkpoint_read(struct sim *s, const char *path, hid_t fid);

#endif
