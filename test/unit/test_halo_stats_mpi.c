/* Halo sizes over the ranks (src/core/halo_stats.c), run as mpirun -n 2
 * (test/unit/CMakeLists.txt: *_mpi.c files). Both ranks build the same 400
 * jittered particles in a box periodic in x, closed in y; after the METIS
 * partition and a halo build, every count halo_stats_gather reports (owned,
 * ghost, remote ghost, sent, partners, bytes per refresh: min, max, total)
 * must equal a brute-force count from the positions and the cell owners:
 * every image (shift 0 or +-L in x) of every particle that lies within the
 * ghost width of a cell of rank r, and is not one of r's own rows, is one
 * ghost on r. The same on one rank (each rank alone on PETSC_COMM_SELF):
 * the periodic images only, no partner, nothing remote.
 * Checks are gathered over the ranks before asserting, so that a failure on
 * one rank does not leave the other waiting in a collective. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/partition.h"
#include "dmhs/halo.h"

#define N    400
#define SIDE 20
#include "mpi_check.h"
/* the ghost width: 7 x 7 coarse cells of edge 1/7; the positions lie on a 1e-3 grid, so no
 * distance to a cell ties it */
#define WIDTH 0.1303

static sim s;
/* the fields a refresh between builds sends (any set: ghost_bytes is theirs) */
static const char *const refresh[] = {"x", "v_est", "rho"};

static void add_particles(particles *ps) {
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    const double v[2] = {0, 0};
    base_x(k, x);
    OK(particles_add_owned(ps, k, PTYPE_FLUID, x, v, 1.0, 1000.0, NULL));
  }
}

/* Distance from y to cell (cx, cy) of the partition's grid. */
static double dist_to_cell(const partition *p, const double y[2], PetscInt cx, PetscInt cy) {
  const PetscInt c[2] = {cx, cy};
  double d2 = 0;
  for (int k = 0; k < 2; k++) {
    const double lo = p->lo[k] + (double)c[k] * p->edge[k], hi = lo + p->edge[k];
    const double gap = y[k] < lo ? lo - y[k] : y[k] > hi ? y[k] - hi : 0.0;
    d2 += gap * gap;
  }
  return sqrt(d2);
}

/* Brute force: from[r][q] = ghosts on rank r whose source is on rank q (r = q: images). */
static void expected_ghosts(PetscInt64 from[2][2]) {
  const double L = s.dom.hi[0] - s.dom.lo[0], shifts[3] = {0.0, L, -L};
  memset(from, 0, 4 * sizeof(PetscInt64));
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    base_x(k, x);
    const PetscMPIInt src = s.part.owner[partition_cell_of(&s.part, x)];
    for (int a = 0; a < 3; a++) {
      const double y[2] = {x[0] + shifts[a], x[1]};
      for (PetscMPIInt r = 0; r < 2; r++) {
        if (a == 0 && src == r)
          continue; /* one of r's own rows */
        PetscBool near = PETSC_FALSE;
        for (PetscInt cy = 0; cy < s.part.nc[1] && !near; cy++)
          for (PetscInt cx = 0; cx < s.part.nc[0] && !near; cx++)
            near = s.part.owner[cy * s.part.nc[0] + cx] == r &&
                   dist_to_cell(&s.part, y, cx, cy) < WIDTH;
        from[r][src] += near;
      }
    }
  }
}

static void check_count(const char *name, const halo_count *c, const PetscInt64 want[2]) {
  const PetscInt64 lo = PetscMin(want[0], want[1]), hi = PetscMax(want[0], want[1]);
  CHECK(c->min == lo && c->max == hi && c->total == want[0] + want[1],
        "%s: min %lld max %lld total %lld, expected %lld %lld %lld", name, (long long)c->min,
        (long long)c->max, (long long)c->total, (long long)lo, (long long)hi,
        (long long)(want[0] + want[1]));
}

static void test_two_ranks(void **state) {
  (void)state;
  problem[0] = 0;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_WORLD;
  assert_int_equal(MPI_Comm_rank(s.comm, &s.rank), 0);
  assert_int_equal(MPI_Comm_size(s.comm, &s.size), 0);
  if (s.size != 2)
    fail_msg("run on 2 ranks (mpirun -n 2), not %d", (int)s.size);
  s.scene_name = "unit";
  s.part.quiet = PETSC_TRUE;
  s.dom = (domain){.lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
  fields_reset();
  OK(particles_create(&s.ps));
  add_particles(&s.ps);
  OK(halo_create(&s.hal, WIDTH, s.comm));
  OK(partition_set_from_options(&s.part, &s));
  s.part.interval = 0;
  OK(partition_setup(&s.part, &s));
  OK(halo_build(&s.hal, &s.dom, &s.part, &s.ps));
  halo_stats st;
  OK(halo_stats_gather(&s.hal, &s.ps, refresh, 3, &st));

  PetscInt64 from[2][2];
  expected_ghosts(from);
  PetscInt64 owned[2] = {0, 0};
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    base_x(k, x);
    owned[s.part.owner[partition_cell_of(&s.part, x)]]++;
  }
  const PetscInt64 ghost[2] = {from[0][0] + from[0][1], from[1][0] + from[1][1]};
  const PetscInt64 remote[2] = {from[0][1], from[1][0]}, sent[2] = {from[1][0], from[0][1]};
  const PetscInt64 partners[2] = {remote[0] || sent[0], remote[1] || sent[1]};
  const PetscInt64 bytes[2] = {remote[0] * st.ghost_bytes, remote[1] * st.ghost_bytes};
  CHECK(st.ranks == 2, "ranks %d", (int)st.ranks);
  CHECK(s.ps.n_ghost == ghost[s.rank], "this rank holds %lld ghosts, the brute force %lld",
        (long long)s.ps.n_ghost, (long long)ghost[s.rank]);
  CHECK(remote[0] > 0 && remote[1] > 0 && from[0][0] + from[1][1] > 0,
        "the case must have ghosts from the other rank and periodic images on some rank");
  check_count("owned", &st.owned, owned);
  check_count("ghost", &st.ghost, ghost);
  check_count("remote_ghost", &st.remote, remote);
  check_count("sent", &st.sent, sent);
  check_count("partners", &st.partners, partners);
  check_count("forward_bytes", &st.forward_bytes, bytes);
  /* x (2 reals), v_est (2), rho (1) */
  CHECK(st.ghost_bytes == 5 * (PetscInt64)sizeof(double), "ghost_bytes %lld",
        (long long)st.ghost_bytes);
  agree("two ranks");
  OK(halo_destroy(&s.hal));
  OK(partition_destroy(&s.part));
  OK(particles_destroy(&s.ps));
}

/* Each rank alone: the periodic images within the width of x = 0 or x = 1. */
static void test_one_rank(void **state) {
  (void)state;
  problem[0] = 0;
  particles ps;
  halo h;
  halo_stats st;
  partition none;
  OK(PetscMemzero(&none, sizeof(none)));
  const domain d = {.lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
  fields_reset();
  OK(particles_create(&ps));
  add_particles(&ps);
  OK(halo_create(&h, WIDTH, PETSC_COMM_SELF));
  OK(halo_build(&h, &d, &none, &ps));
  OK(halo_stats_gather(&h, &ps, refresh, 3, &st));
  PetscInt64 images = 0;
  for (PetscInt64 k = 0; k < N; k++) {
    double x[2];
    base_x(k, x);
    images += (x[0] < WIDTH) + (1.0 - x[0] <= WIDTH);
  }
  CHECK(st.ranks == 1 && images > 0, "ranks %d, %lld images", (int)st.ranks, (long long)images);
  const halo_count want_owned = {N, N, N}, want_ghost = {images, images, images}, zero = {0, 0, 0};
  CHECK(!memcmp(&st.owned, &want_owned, sizeof(zero)), "owned (one rank)");
  CHECK(!memcmp(&st.ghost, &want_ghost, sizeof(zero)),
        "ghost (one rank): %lld %lld %lld, expected %lld", (long long)st.ghost.min,
        (long long)st.ghost.max, (long long)st.ghost.total, (long long)images);
  CHECK(!memcmp(&st.remote, &zero, sizeof(zero)) && !memcmp(&st.sent, &zero, sizeof(zero)) &&
            !memcmp(&st.partners, &zero, sizeof(zero)) &&
            !memcmp(&st.forward_bytes, &zero, sizeof(zero)),
        "one rank: something remote");
  agree("one rank");
  OK(halo_destroy(&h));
  OK(particles_destroy(&ps));
}

int main(int argc, char **argv) {
  (void)argc;
  (void)argv;
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_two_ranks),
      cmocka_unit_test(test_one_rank),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
