/* What the MPI unit tests share: checks that record a rank's first failure
 * instead of stopping it (a rank that stops leaves the other in a collective),
 * the verdict taken together, and the jittered lattice both ranks build.
 * Define SIDE (particles per row of the lattice) before including. */
#ifndef DMHS_TEST_MPI_CHECK_H
#define DMHS_TEST_MPI_CHECK_H
#include <stdio.h>
#include "unit_common.h"

static char problem[512]; /* this rank's first failed check */

#define CHECK(cond, ...)                                                                           \
  do {                                                                                             \
    if (!(cond) && !problem[0])                                                                    \
      snprintf(problem, sizeof(problem), __VA_ARGS__);                                             \
  } while (0)

/* Fails on every rank when a check failed on any. */
static void agree(const char *where) {
  int mine = problem[0] != 0, any = 0, rank = -1;
  assert_int_equal(MPI_Comm_rank(PETSC_COMM_WORLD, &rank), 0);
  assert_int_equal(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD), 0);
  if (any)
    fail_msg("%s: rank %d: %s", where, rank, mine ? problem : "(failed on the other rank)");
}

/* The lattice position of particle k, jittered (the same on every rank). */
static inline void base_x(PetscInt64 k, double x[2]) {
  x[0] = ((double)(k % SIDE) + 0.5) / SIDE + (double)((k * 37) % 11 - 5) * 1e-3;
  x[1] = ((double)(k / SIDE) + 0.5) / SIDE + (double)((k * 53) % 7 - 3) * 1e-3;
}

#endif
