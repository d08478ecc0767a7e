/* The largest value over the ranks and its particle's gid (extreme_max, extreme_consider:
 * src/core/extreme.c), run as mpirun -n 2. Proves:
 *   - a rank's search keeps the largest value, ties to the lower gid, and never a NaN or
 *     -INFINITY;
 *   - over the ranks the largest wins wherever it is, equal values go to the lowest gid
 *     whichever rank holds it, a rank without a candidate (gid < 0) takes no part, and
 *     with none anywhere the answer is EXTREME_NONE;
 *   - a gid beyond 32 bits comes back whole.
 * Checks are gathered over the ranks before asserting (mpi_check.h). */
#include "unit_common.h"
#include "dmhs/extreme.h"

#define SIDE 1 /* mpi_check.h's lattice, not used here */
#include "mpi_check.h"

static void test_consider(void **state) {
  extreme_value e = EXTREME_NONE;
  (void)state;
  extreme_consider(&e, NAN, 1);
  extreme_consider(&e, -INFINITY, 2);
  assert_true(e.gid == -1 && e.value == -INFINITY);
  extreme_consider(&e, 3.0, 10);
  extreme_consider(&e, 3.0, 12); /* tie, higher gid: kept out */
  extreme_consider(&e, 2.0, 1);  /* smaller */
  extreme_consider(&e, NAN, 0);
  assert_true(e.gid == 10 && e.value == 3.0);
  extreme_consider(&e, 3.0, 4); /* tie, lower gid */
  assert_true(e.gid == 4 && e.value == 3.0);
  extreme_consider(&e, 3.5, 40);
  assert_true(e.gid == 40 && e.value == 3.5);
}

static void test_ranks(void **state) {
  PetscMPIInt rank, size;
  extreme_value best;
  (void)state;
  assert_int_equal(MPI_Comm_rank(PETSC_COMM_WORLD, &rank), 0);
  assert_int_equal(MPI_Comm_size(PETSC_COMM_WORLD, &size), 0);
  const PetscBool last = rank == size - 1 ? PETSC_TRUE : PETSC_FALSE;
  /* the largest on the last rank */
  OK(extreme_max(PETSC_COMM_WORLD, (extreme_value){last ? 9.0 : 1.0 + rank, 100 + rank}, &best));
  CHECK(best.value == 9.0 && best.gid == 100 + size - 1, "largest: %g gid %lld", best.value,
        (long long)best.gid);
  /* equal values: the lowest gid, on the last rank, then on rank 0 */
  OK(extreme_max(PETSC_COMM_WORLD, (extreme_value){5.0, last ? 3 : 7 + rank}, &best));
  CHECK(best.value == 5.0 && best.gid == 3, "tie (last lowest): gid %lld", (long long)best.gid);
  OK(extreme_max(PETSC_COMM_WORLD, (extreme_value){5.0, rank == 0 ? 3 : 7 + rank}, &best));
  CHECK(best.value == 5.0 && best.gid == 3, "tie (rank 0 lowest): gid %lld", (long long)best.gid);
  /* rank 0 has none (even with a large value), the others' largest wins */
  OK(extreme_max(PETSC_COMM_WORLD,
                 rank == 0 ? (extreme_value){1e300, -1} : (extreme_value){-2.0 + rank, 50 + rank},
                 &best));
  if (size > 1)
    CHECK(best.value == -2.0 + (size - 1) && best.gid == 50 + size - 1,
          "rank 0 without: %g gid %lld", best.value, (long long)best.gid);
  else
    CHECK(best.gid == -1 && best.value == -INFINITY, "alone without: gid %lld",
          (long long)best.gid);
  /* none anywhere */
  OK(extreme_max(PETSC_COMM_WORLD, EXTREME_NONE, &best));
  CHECK(best.gid == -1 && best.value == -INFINITY, "none: %g gid %lld", best.value,
        (long long)best.gid);
  /* a gid of 41 bits */
  const PetscInt64 big = ((PetscInt64)1 << 40) + 5;
  OK(extreme_max(PETSC_COMM_WORLD, (extreme_value){last ? 1.0 : 0.5, last ? big : 1}, &best));
  CHECK(best.gid == big, "64-bit gid: %lld", (long long)best.gid);
  agree("over the ranks");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_consider),
      cmocka_unit_test(test_ranks),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
