/* The largest value over all ranks and the global id of the particle that holds it, ties
 * to the lowest gid (MPI_MAXLOC's rule, with a 64-bit gid): the same particle on any rank
 * count. The smallest is the largest of the negated values. */
#ifndef DMHS_EXTREME_H
#define DMHS_EXTREME_H
#include <math.h>
#include <petscsys.h>

/* A value and the gid of its particle; gid < 0: none. */
typedef struct {
  double value;
  PetscInt64 gid;
} extreme_value;

/* None yet: what a rank's search starts from. */
#define EXTREME_NONE ((extreme_value){-INFINITY, -1})

/* Keeps (value, gid) in *best when its value is larger, or equal with a lower gid (a NaN
 * or -INFINITY is never kept). */
static inline void extreme_consider(extreme_value *best, double value, PetscInt64 gid) {
  if (value > best->value || (value == best->value && gid < best->gid)) {
    best->value = value;
    best->gid = gid;
  }
}

/* Collective: the largest of every rank's `mine` (those with gid < 0 take no part), ties
 * to the lowest gid; EXTREME_NONE when no rank has one. */
PetscErrorCode extreme_max(MPI_Comm comm, extreme_value mine, extreme_value *best);

#endif
