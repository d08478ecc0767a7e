/* The distributed bond/angle store on 2 ranks (src/core/topology.c,
 * topology_exchange.c); run as mpirun -n 2. Both ranks build the same 400
 * particles on a jittered lattice, with a bond between row neighbours and an
 * angle over every three in a row, all added on both ranks as a scene does.
 * Proves:
 *   - after the partition and the first resolution, each rank's store holds
 *     exactly the bonds and angles with an end it owns, in increasing id order,
 *     and the global counts are right;
 *   - after a migration that moves many particles (a shift across the periodic
 *     boundary and a mirror), the same holds: the entries travelled with their particles;
 *   - a collective add with the bonds given on different ranks numbers them in
 *     gid order (the same ids whichever rank gave which), both ranks keep those
 *     of their owned particles, and the structure is marked changed;
 *   - a collective removal given on one rank removes the bonds on both, with
 *     the counts per type;
 *   - every local bond entry joins the right two gids, its owned end's force is
 *     summed here, and no bond is lost: the energy weights add up to the count.
 * Checks are gathered over the ranks before asserting (mpi_check.h). */
#include <string.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/partition.h"
#include "dmhs/migrate.h"
#include "dmhs/halo.h"

#define N    400
#define SIDE 20
#include "mpi_check.h"

static sim s;

/* The structure: a bond (k, k+1) inside each row, an angle (k, k+1, k+2). */
static PetscBool is_bond(PetscInt64 a, PetscInt64 b) {
  return b == a + 1 && a / SIDE == b / SIDE ? PETSC_TRUE : PETSC_FALSE;
}

static PetscBool owned_here(PetscInt64 g) {
  for (PetscInt i = 0; i < s.ps.n_owned; i++)
    if (s.ps.gid[i] == g)
      return PETSC_TRUE;
  return PETSC_FALSE;
}

/* Store = every entry of the structure with an owned end, in id order; the counts. */
static void check_store(PetscInt64 extra_bonds, const char *where) {
  const topology *t = s.topo;
  PetscInt want_b = 0, want_a = 0;
  for (PetscInt64 k = 0; k < N; k++) {
    if (is_bond(k, k + 1) && (owned_here(k) || owned_here(k + 1)))
      want_b++;
    if (is_bond(k, k + 1) && is_bond(k + 1, k + 2) &&
        (owned_here(k) || owned_here(k + 1) || owned_here(k + 2)))
      want_a++;
  }
  PetscInt static_b = 0;
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    CHECK(b == 0 || t->bond_id[b] > t->bond_id[b - 1], "%s: bond ids out of order at %d", where,
          (int)b);
    CHECK(owned_here(t->bond_gid[b][0]) || owned_here(t->bond_gid[b][1]),
          "%s: bond %lld-%lld held without an owned end", where, (long long)t->bond_gid[b][0],
          (long long)t->bond_gid[b][1]);
    if (t->bond_type[b] == 0) {
      CHECK(is_bond(t->bond_gid[b][0], t->bond_gid[b][1]), "%s: unknown bond", where);
      static_b++;
    }
  }
  CHECK(static_b == want_b, "%s: %d scene bonds held, expected %d", where, (int)static_b,
        (int)want_b);
  CHECK(t->n_angles == want_a, "%s: %d angles held, expected %d", where, (int)t->n_angles,
        (int)want_a);
  CHECK(t->n_bonds_global == (SIDE - 1) * SIDE + extra_bonds, "%s: %lld bonds in all", where,
        (long long)t->n_bonds_global);
  CHECK(t->n_angles_global == (SIDE - 2) * SIDE, "%s: %lld angles in all", where,
        (long long)t->n_angles_global);
  /* local entries: the energy weights of all ranks count every bond once */
  double w = 0, w_all = 0;
  for (PetscInt e = 0; e < t->n_bond_local; e++) {
    const PetscInt i = t->bond[e][0], j = t->bond[e][1];
    CHECK(i < s.ps.n_owned || j < s.ps.n_owned, "%s: a local bond without an owned row", where);
    w += t->bond_weight[e];
  }
  assert_int_equal(MPI_Allreduce(&w, &w_all, 1, MPI_DOUBLE, MPI_SUM, s.comm), 0);
  CHECK(w_all == (double)t->n_bonds_global, "%s: bond weights add up to %g, %lld bonds", where,
        w_all, (long long)t->n_bonds_global);
  agree(where);
}

static void rebuild(void) {
  OK(halo_build(&s.hal, &s.dom, &s.part, &s.ps));
  OK(topology_resolve(s.topo, &s.ps));
}

static void test_distributed_store(void **state) {
  (void)state;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_WORLD;
  assert_int_equal(MPI_Comm_rank(s.comm, &s.rank), 0);
  assert_int_equal(MPI_Comm_size(s.comm, &s.size), 0);
  if (s.size != 2)
    fail_msg("run on 2 ranks (mpirun -n 2), not %d", (int)s.size);
  s.scene_name = "unit";
  s.part.quiet = PETSC_TRUE;
  s.dom = (domain){.lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
  OK(halo_create(&s.hal, 0.125, s.comm)); /* 8 x 8 coarse cells; bonds are 0.05 long */
  fields_reset();
  OK(particles_create(&s.ps));
  OK(topology_create(&s.topo));
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    const double v[2] = {0, 0};
    base_x(k, x);
    OK(particles_add_owned(&s.ps, k, PTYPE_SOLID, x, v, 1.0, 1000.0, NULL));
    if (is_bond(k, k + 1))
      OK(topology_add_bond(s.topo, k, k + 1, 0));
    if (is_bond(k, k + 1) && is_bond(k + 1, k + 2))
      OK(topology_add_angle(s.topo, k, k + 1, k + 2, 0));
  }
  OK(partition_set_from_options(&s.part, &s));
  s.part.interval = 0;
  OK(partition_setup(&s.part, &s));
  rebuild();
  CHECK(s.topo->n_bonds < (SIDE - 1) * SIDE, "rank %d kept the whole structure", (int)s.rank);
  check_store(0, "first resolution");

  /* many particles change rank: their entries go with them */
  for (PetscInt i = 0; i < s.ps.n_owned; i++) { /* METIS may cut along x or y: both change */
    s.ps.x[i][0] += 0.37;
    s.ps.x[i][1] = 1.0 - s.ps.x[i][1];
    domain_wrap(&s.dom, s.ps.x[i]);
  }
  s.step = 1;
  OK(migrate_particles(&s));
  PetscInt64 moved = 0;
  assert_int_equal(MPI_Allreduce(&s.mig.moved, &moved, 1, MPIU_INT64, MPI_SUM, s.comm), 0);
  CHECK(moved > N / 10, "only %lld particles changed rank", (long long)moved);
  rebuild();
  check_store(0, "after migration");

  /* collective add: bonds (k, k + SIDE) down column 3, given half by each rank, the rank
   * that gives one not necessarily an owner of it */
  PetscInt64 give[SIDE][2];
  PetscInt type[SIDE], n_give = 0;
  double r0[SIDE];
  for (PetscInt64 row = 0; row + 1 < SIDE; row++)
    if ((row % 2) == s.rank) {
      give[n_give][0] = row * SIDE + 3;
      give[n_give][1] = (row + 1) * SIDE + 3;
      type[n_give] = 1;
      r0[n_give++] = 0.05;
    }
  const PetscInt64 first_id = s.topo->next_bond_id;
  OK(topology_add_bonds(s.topo, &s.ps, s.comm, n_give, (const PetscInt64(*)[2])give, type, r0));
  CHECK(s.topo->changed, "the add did not mark the structure changed");
  CHECK(s.topo->n_bonds_of_type[1] == SIDE - 1, "%lld bonds of type 1",
        (long long)s.topo->n_bonds_of_type[1]);
  for (PetscInt b = 0; b < s.topo->n_bonds; b++)
    if (s.topo->bond_type[b] == 1) /* numbered down the column, whoever gave it */
      CHECK(s.topo->bond_id[b] == first_id + s.topo->bond_gid[b][0] / SIDE,
            "bond %lld-%lld got id %lld", (long long)s.topo->bond_gid[b][0],
            (long long)s.topo->bond_gid[b][1], (long long)s.topo->bond_id[b]);
  PetscInt held = 0;
  for (PetscInt64 row = 0; row + 1 < SIDE; row++)
    held += owned_here(row * SIDE + 3) || owned_here((row + 1) * SIDE + 3);
  PetscInt held_store = 0;
  for (PetscInt b = 0; b < s.topo->n_bonds; b++)
    held_store += s.topo->bond_type[b] == 1;
  CHECK(held_store == held, "%d column bonds held, %d expected", (int)held_store, (int)held);
  rebuild();
  check_store(SIDE - 1, "after the collective add");

  /* collective removal, given on rank 1 only: the column's first 5 bonds, either order */
  PetscInt64 gone[5][2];
  for (int k = 0; k < 5; k++) {
    gone[k][0] = (k + 1) * SIDE + 3;
    gone[k][1] = k * SIDE + 3;
  }
  OK(topology_remove_bonds(s.topo, &s.ps, s.comm, s.rank == 1 ? 5 : 0, (const PetscInt64(*)[2])gone,
                           1));
  CHECK(s.topo->n_bonds_of_type[1] == SIDE - 6, "%lld bonds of type 1 after the removal",
        (long long)s.topo->n_bonds_of_type[1]);
  for (PetscInt b = 0; b < s.topo->n_bonds; b++)
    CHECK(s.topo->bond_type[b] != 1 || s.topo->bond_gid[b][0] >= 5 * SIDE,
          "removed bond %lld-%lld still held", (long long)s.topo->bond_gid[b][0],
          (long long)s.topo->bond_gid[b][1]);
  rebuild();
  check_store(SIDE - 6, "after the collective removal");

  OK(topology_destroy(&s.topo));
  OK(halo_destroy(&s.hal));
  OK(partition_destroy(&s.part));
  OK(particles_destroy(&s.ps));
  options_forget();
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_distributed_store),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
