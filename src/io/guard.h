/* The last guard before a snapshot or checkpoint is written (private to
 * src/io): no non-finite value ever reaches a file, whatever let it through
 * the per-step state check. */
#ifndef DMHS_IO_GUARD_H
#define DMHS_IO_GUARD_H
#include <petscsys.h>

struct sim;

/* Every real field with one of `flags` (FIELD_OUTPUT, FIELD_CHECKPOINT) must be
 * finite for every owned particle; otherwise an error naming path, the field,
 * the particle's gid, the step and the time. Local: the rank that finds the
 * value raises the error (main aborts the others). */
PetscErrorCode io_guard_finite(const struct sim *s, unsigned flags, const char *path);

#endif
