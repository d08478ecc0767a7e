/* Partition and migration between 2 ranks (src/core/partition.c, migrate.c);
 * run as mpirun -n 2 (test/unit/CMakeLists.txt: *_mpi.c files). Both ranks
 * build the same 400 particles, every field a known function of the gid.
 * Proves:
 *   - partition_setup keeps on each rank exactly the particles of its cells,
 *     each once, both ranks non-empty and balanced (imbalance <= 1.2);
 *   - migrate_particles, after a shift across the periodic boundary (and a
 *     mirror in y), leaves
 *     every particle on the owner of its cell, each gid once over the ranks,
 *     every FIELD_MIGRATE field (an optional one included) intact; it moves
 *     exactly the particles whose cell is owned elsewhere (moved counter),
 *     keeps the staying ones in their order and appends the arrivals in the
 *     order the other rank held them;
 *   - all particles into one cell: one rank holds all 400, the other none;
 *   - spread out again with -partition_interval 1: the imbalance (2) triggers
 *     a repartition, after which the work is balanced again;
 *   - -debug_migration passes on all of this and fails on both ranks when one
 *     rank loses a particle.
 * Checks are gathered over the ranks before asserting, so that a failure on
 * one rank does not leave the other waiting in a collective. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/partition.h"
#include "dmhs/migrate.h"

#define N    400
#define SIDE 20
#include "mpi_check.h"

static sim s;

/* Positions of the phases: 0 lattice; 1 shifted by 0.37 in x (wrapped) and mirrored in y (with
 * x periodic, METIS may cut the box along x or along y: either way particles change rank);
 * 2 all in cell (4, 4). */
static void x_of(int phase, PetscInt64 k, double x[2]) {
  base_x(k, x);
  if (phase == 1) {
    x[0] += 0.37;
    x[1] = 1.0 - x[1];
    domain_wrap(&s.dom, x);
  } else if (phase == 2) {
    x[0] = 0.51 + 0.1 * x[0];
    x[1] = 0.52 + 0.1 * x[1];
  }
}

static void set_fields(PetscInt i) {
  particles *ps = &s.ps;
  const double k = (double)ps->gid[i];
  ps->v[i][0] = k, ps->v[i][1] = -2 * k;
  ps->v_est[i][0] = k + 0.5, ps->v_est[i][1] = 1.0;
  ps->a[i][0] = 3 * k, ps->a[i][1] = 7.0;
  ps->x0[i][0] = -k, ps->x0[i][1] = 1e-3 * k;
  ps->x_build[i][0] = 0.5 * k, ps->x_build[i][1] = 0.25 * k;
  ps->a_hold[i][0] = k, ps->a_hold[i][1] = k + 1;
  ps->drho[i] = -k;
  ps->tracer[i] = 1000 + (PetscInt)ps->gid[i];
}

static void check_fields(PetscInt i, int phase) {
  const particles *ps = &s.ps;
  const PetscInt64 g = ps->gid[i];
  const double k = (double)g;
  double x[2];
  x_of(phase, g, x);
  CHECK(ps->x[i][0] == x[0] && ps->x[i][1] == x[1], "gid %lld: x (%g, %g), expected (%g, %g)",
        (long long)g, ps->x[i][0], ps->x[i][1], x[0], x[1]);
  CHECK(ps->type[i] == (PetscInt)(g % PTYPE_COUNT) && ps->tracer[i] == 1000 + (PetscInt)g,
        "gid %lld: type/tracer", (long long)g);
  CHECK(ps->v[i][0] == k && ps->v[i][1] == -2 * k, "gid %lld: v", (long long)g);
  CHECK(ps->v_est[i][0] == k + 0.5 && ps->v_est[i][1] == 1.0, "gid %lld: v_est", (long long)g);
  CHECK(ps->a[i][0] == 3 * k && ps->a[i][1] == 7.0, "gid %lld: a", (long long)g);
  CHECK(ps->x0[i][0] == -k && ps->x0[i][1] == 1e-3 * k, "gid %lld: x0", (long long)g);
  CHECK(ps->x_build[i][0] == 0.5 * k && ps->x_build[i][1] == 0.25 * k, "gid %lld: x_build",
        (long long)g);
  CHECK(ps->a_hold[i][0] == k && ps->a_hold[i][1] == k + 1, "gid %lld: a_hold (optional field)",
        (long long)g);
  CHECK(ps->mass[i] == 1.0 + k && ps->rho[i] == 1000.0 + k / 8 && ps->drho[i] == -k,
        "gid %lld: mass/rho/drho", (long long)g);
}

/* Every particle on the owner of its cell with its fields; each gid once over the ranks. */
static void check_all(int phase, const char *where) {
  for (PetscInt i = 0; i < s.ps.n_owned; i++) {
    const PetscMPIInt owner = s.part.owner[partition_cell_of(&s.part, s.ps.x[i])];
    CHECK(owner == s.rank, "gid %lld is on rank %d, its cell on rank %d", (long long)s.ps.gid[i],
          (int)s.rank, (int)owner);
    check_fields(i, phase);
  }
  PetscMPIInt n = (PetscMPIInt)s.ps.n_owned, counts[2] = {0, 0}, displ[2] = {0, 0};
  PetscInt64 all[N + 8];
  assert_int_equal(MPI_Allgather(&n, 1, MPI_INT, counts, 1, MPI_INT, PETSC_COMM_WORLD), 0);
  CHECK(counts[0] + counts[1] == N, "%d + %d particles over the ranks, expected %d", counts[0],
        counts[1], N);
  if (counts[0] + counts[1] <= N + 8) {
    displ[1] = counts[0];
    assert_int_equal(
        MPI_Allgatherv(s.ps.gid, n, MPIU_INT64, all, counts, displ, MPIU_INT64, PETSC_COMM_WORLD),
        0);
    char seen[N] = {0};
    for (int k = 0; k < counts[0] + counts[1]; k++) {
      CHECK(all[k] >= 0 && all[k] < N && !seen[all[k]], "gid %lld missing, repeated or unknown",
            (long long)all[k]);
      if (all[k] >= 0 && all[k] < N)
        seen[all[k]] = 1;
    }
  }
  agree(where);
}

/* Moves particles to the positions of `phase`; returns how many this rank must send. */
static PetscInt move_to(int phase, PetscInt64 *leaving) {
  PetscInt n = 0;
  for (PetscInt i = 0; i < s.ps.n_owned; i++) {
    x_of(phase, s.ps.gid[i], s.ps.x[i]);
    if (s.part.owner[partition_cell_of(&s.part, s.ps.x[i])] != s.rank) {
      if (leaving)
        leaving[n] = s.ps.gid[i];
      n++;
    }
  }
  return n;
}

static void test_partition_and_migrate(void **state) {
  (void)state;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_WORLD;
  assert_int_equal(MPI_Comm_rank(s.comm, &s.rank), 0);
  assert_int_equal(MPI_Comm_size(s.comm, &s.size), 0);
  if (s.size != 2)
    fail_msg("run on 2 ranks (mpirun -n 2), not %d", (int)s.size);
  s.scene_name = "unit";
  s.part.quiet = PETSC_TRUE; /* no "repartitioned" line */
  s.dom = (domain){.lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
  s.hal.width = 0.125; /* 8 x 8 coarse cells */
  fields_reset();
  OK(fields_enable("a_hold"));
  OK(fields_enable("x0"));
  OK(fields_enable("tracer"));
  OK(unit_enable_sph_fields());
  OK(particles_create(&s.ps));
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    const double v[2] = {0, 0};
    PetscInt i;
    base_x(k, x);
    OK(particles_add_owned(&s.ps, k, (particle_type)(k % PTYPE_COUNT), x, v, 1.0 + (double)k,
                           1000.0 + (double)k / 8, &i));
    set_fields(i);
  }
  OK(partition_set_from_options(&s.part, &s));
  s.part.interval = 0; /* no repartition until phase 3 */
  OK(partition_setup(&s.part, &s));
  CHECK(s.ps.n_owned > 0, "rank %d kept no particle", (int)s.rank);
  CHECK(s.part.imbalance <= 1.2, "imbalance %g after the first partition", s.part.imbalance);
  check_all(0, "partition_setup");
  s.mig.enabled = PETSC_TRUE; /* -debug_migration */
  OK(migrate_check_ids(&s.mig, &s));

  /* phase 1: across the periodic boundary */
  PetscInt64 *leaving, *arriving;
  OK(PetscMalloc2(N, &leaving, N, &arriving));
  PetscInt64 *stay;
  OK(PetscMalloc1(N, &stay));
  const PetscInt n_leave = move_to(1, leaving);
  PetscInt n_stay = 0;
  for (PetscInt i = 0; i < s.ps.n_owned; i++)
    if (s.part.owner[partition_cell_of(&s.part, s.ps.x[i])] == s.rank)
      stay[n_stay++] = s.ps.gid[i];
  PetscMPIInt n_arrive = 0, nl = (PetscMPIInt)n_leave;
  const PetscMPIInt other = 1 - s.rank;
  assert_int_equal(MPI_Sendrecv(&nl, 1, MPI_INT, other, 0, &n_arrive, 1, MPI_INT, other, 0, s.comm,
                                MPI_STATUS_IGNORE),
                   0);
  assert_int_equal(MPI_Sendrecv(leaving, nl, MPIU_INT64, other, 1, arriving, n_arrive, MPIU_INT64,
                                other, 1, s.comm, MPI_STATUS_IGNORE),
                   0);
  s.step = 1;
  OK(migrate_particles(&s));
  check_all(1, "phase 1 (periodic shift, mirror)");
  CHECK(s.mig.moved == n_leave, "moved %lld, expected %d", (long long)s.mig.moved, (int)n_leave);
  CHECK(s.ps.n_owned == n_stay + n_arrive, "%d rows, expected %d staying + %d arriving",
        (int)s.ps.n_owned, (int)n_stay, (int)n_arrive);
  for (PetscInt i = 0; i < n_stay && i < s.ps.n_owned; i++)
    CHECK(s.ps.gid[i] == stay[i], "row %d: gid %lld, expected the staying gid %lld", (int)i,
          (long long)s.ps.gid[i], (long long)stay[i]);
  for (PetscInt e = 0; e < n_arrive && n_stay + e < s.ps.n_owned; e++)
    CHECK(s.ps.gid[n_stay + e] == arriving[e], "arrival %d: gid %lld, expected %lld", (int)e,
          (long long)s.ps.gid[n_stay + e], (long long)arriving[e]);
  PetscInt64 moved_total = 0;
  assert_int_equal(MPI_Allreduce(&s.mig.moved, &moved_total, 1, MPIU_INT64, MPI_SUM, s.comm), 0);
  CHECK(moved_total > N / 10,
        "only %lld particles changed rank: the shift does not test the exchange",
        (long long)moved_total);
  agree("phase 1 (order, counts)");

  /* phase 2: everything into one cell, owned by one rank */
  s.step = 2;
  move_to(2, NULL);
  OK(migrate_particles(&s));
  check_all(2, "phase 2 (one cell)");
  const PetscMPIInt owner = s.part.owner[partition_cell_of(&s.part, (double[2]){0.55, 0.55})];
  CHECK(s.ps.n_owned == (owner == s.rank ? N : 0), "rank %d holds %d particles", (int)s.rank,
        (int)s.ps.n_owned);
  agree("phase 2 (counts)");

  /* phase 3: spread out again; the imbalance (2) makes partition_check repartition */
  s.step = 3;
  s.part.interval = 1;
  move_to(0, NULL);
  OK(migrate_particles(&s));
  check_all(0, "phase 3 (repartitioned)");
  CHECK(s.part.n_repartitions == 1, "%d repartitions, expected 1", (int)s.part.n_repartitions);
  OK(partition_measure_imbalance(&s.part, &s));
  CHECK(s.part.imbalance <= 1.2 && s.ps.n_owned > 0,
        "after the repartition: imbalance %g, %d particles here", s.part.imbalance,
        (int)s.ps.n_owned);
  agree("phase 3 (balance)");

  /* -debug_migration: a particle lost on rank 1 is seen on both */
  if (s.rank == 1)
    s.ps.n_owned--;
  assert_int_equal(migrate_check_ids(&s.mig, &s), PETSC_ERR_PLIB);
  OK(PetscFree2(leaving, arriving));
  OK(PetscFree(stay));
  OK(partition_destroy(&s.part));
  OK(particles_destroy(&s.ps));
  options_forget();
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_partition_and_migrate),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
