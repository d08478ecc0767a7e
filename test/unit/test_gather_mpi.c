/* Blocks gathered on every rank (gather_all, src/core/gather.c), run as mpirun -n 2.
 * Proves:
 *   - every rank receives every rank's items in rank order, byte for byte, with their
 *     count and the index of its own first item, whatever the item's size;
 *   - a rank with no items takes part (and gets the others'), and with none anywhere the
 *     result is empty but allocated;
 *   - more bytes than an MPI count holds, on one rank or over the ranks, is an error on
 *     every rank (none left waiting in the gather), before any item is read.
 * Checks are gathered over the ranks before asserting (mpi_check.h). */
#include <limits.h>
#include "unit_common.h"
#include "dmhs/gather.h"

#define SIDE 1 /* mpi_check.h's lattice, not used here */
#include "mpi_check.h"

typedef struct {
  PetscInt64 rank, k;
  double x;
} item;

static void test_rank_order(void **state) {
  PetscMPIInt rank, size;
  item mine[8], *all = NULL;
  size_t n_all = 0, start = 99, want_start = 0;
  (void)state;
  assert_int_equal(MPI_Comm_rank(PETSC_COMM_WORLD, &rank), 0);
  assert_int_equal(MPI_Comm_size(PETSC_COMM_WORLD, &size), 0);
  for (PetscInt64 k = 0; k < rank + 2; k++)
    mine[k] = (item){rank, k, rank + (double)k / 8};
  OK(gather_all(PETSC_COMM_WORLD, "test items", mine, (size_t)rank + 2, sizeof(item), &all, &n_all,
                &start));
  size_t at = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    if (r == rank)
      want_start = at;
    for (PetscInt64 k = 0; k < r + 2; k++, at++)
      CHECK(at < n_all && all[at].rank == r && all[at].k == k && all[at].x == r + (double)k / 8,
            "item %zu is not rank %d's item %lld", at, (int)r, (long long)k);
  }
  CHECK(n_all == at, "%zu items gathered, %zu given", n_all, at);
  CHECK(start == want_start, "own items start at %zu, expected %zu", start, want_start);
  OK(PetscFree(all));
  agree("rank order");
}

static void test_empty(void **state) {
  PetscMPIInt rank, size;
  double mine[3] = {1.5, -2.5, 3.5}, *all = NULL;
  size_t n_all = 99, start = 99;
  (void)state;
  assert_int_equal(MPI_Comm_rank(PETSC_COMM_WORLD, &rank), 0);
  assert_int_equal(MPI_Comm_size(PETSC_COMM_WORLD, &size), 0);
  /* only the last rank has items; rank 0 passes none (and no buffer) */
  const PetscBool last = rank == size - 1 ? PETSC_TRUE : PETSC_FALSE;
  OK(gather_all(PETSC_COMM_WORLD, "test values", last ? mine : NULL, last ? 3 : 0, sizeof(double),
                &all, &n_all, &start));
  CHECK(all && n_all == 3 && all[0] == 1.5 && all[1] == -2.5 && all[2] == 3.5,
        "%zu values gathered from the last rank", n_all);
  CHECK(start == 0, "own items start at %zu with none before", start);
  OK(PetscFree(all));
  /* none anywhere: an empty result, still allocated; start not asked for */
  OK(gather_all(PETSC_COMM_WORLD, "test values", NULL, 0, sizeof(double), &all, &n_all, NULL));
  CHECK(all && n_all == 0, "%zu values gathered from nothing", n_all);
  OK(PetscFree(all));
  agree("empty ranks");
}

static void test_overflow(void **state) {
  PetscMPIInt rank, size;
  double small[1] = {0}, *all = NULL;
  size_t n_all = 0;
  (void)state;
  assert_int_equal(MPI_Comm_rank(PETSC_COMM_WORLD, &rank), 0);
  assert_int_equal(MPI_Comm_size(PETSC_COMM_WORLD, &size), 0);
  /* one rank's bytes: the last claims INT_MAX / 8 + 1 doubles (never read) */
  const size_t too_many = (size_t)INT_MAX / sizeof(double) + 1;
  const PetscErrorCode one =
      gather_all(PETSC_COMM_WORLD, "test values", small, rank == size - 1 ? too_many : 1,
                 sizeof(double), &all, &n_all, NULL);
  CHECK(one != 0, "%zu doubles on one rank were gathered", too_many);
  /* the sum over the ranks: each claims a share that fits alone, not together */
  const size_t share = (size_t)INT_MAX / sizeof(double) / (size_t)size + 1;
  const PetscErrorCode sum = size > 1 ? gather_all(PETSC_COMM_WORLD, "test values", small, share,
                                                   sizeof(double), &all, &n_all, NULL)
                                      : 1;
  CHECK(sum != 0, "%zu doubles on each of %d ranks were gathered", share, (int)size);
  /* a collective still works afterwards: nobody was left in the gather */
  OK(gather_all(PETSC_COMM_WORLD, "test values", small, 1, sizeof(double), &all, &n_all, NULL));
  CHECK(n_all == (size_t)size, "%zu values after the refused gathers", n_all);
  OK(PetscFree(all));
  agree("overflow");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_rank_order),
      cmocka_unit_test(test_empty),
      cmocka_unit_test(test_overflow),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
