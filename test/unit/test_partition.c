/* Domain decomposition (src/core/partition.c) on one process; the particles'
 * move between real ranks is unit_migrate_mpi. Proves:
 *   - the coarse grid: nc = floor(L / ghost width) cells per axis (L/64 with
 *     no reach), edges L/nc >= the ghost width, row-major cells, positions
 *     outside the box clamped to the edge cells;
 *   - the options' defaults and their refusals;
 *   - the METIS partition into 2 parts (partition_compute with two parts,
 *     run on this one process): every cell owned by 0 or 1, both parts
 *     connected, the work (16 per particle + 1 per cell) balanced within 10 %,
 *     the same owners on a second run (fixed seed), and the frontier exactly
 *     the part-0 cells with a 3 x 3 neighbour in part 1 or across a periodic
 *     boundary. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/partition.h"

static sim s;

static void make(double lx, double ly, PetscBool periodic_x, double width) {
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  s.size = 1;
  s.rank = 0;
  s.scene_name = "unit";
  s.dom = (domain){.lo = {0.0, 0.0}, .hi = {lx, ly}, .periodic = {periodic_x, PETSC_FALSE}};
  s.hal.width = width;
  fields_reset();
  OK(particles_create(&s.ps));
}

static void add(double x, double y) {
  const double p[2] = {x, y}, v[2] = {0, 0};
  OK(particles_add_owned(&s.ps, s.ps.n_owned, PTYPE_FLUID, p, v, 1.0, 1.0, NULL));
}

static void done(void) {
  OK(partition_destroy(&s.part));
  OK(particles_destroy(&s.ps));
}

static void test_grid(void **state) {
  (void)state;
  make(1.0, 0.6, PETSC_FALSE, 0.25);
  add(0.5, 0.3);
  OK(partition_setup(&s.part, &s));
  const partition *p = &s.part;
  assert_int_equal(p->nc[0], 4);
  assert_int_equal(p->nc[1], 2); /* floor(0.6 / 0.25) */
  assert_int_equal(p->n_cells, 8);
  assert_close(p->edge[0], 0.25, 0);
  assert_close(p->edge[1], 0.3, 1e-16);
  for (PetscInt c = 0; c < 8; c++)
    assert_int_equal(p->owner[c], 0);
  assert_int_equal(s.ps.n_owned, 1); /* one rank keeps everything */
  const struct {
    double x[2];
    PetscInt cell;
  } at[] = {{{0.1, 0.1}, 0},  {{0.3, 0.35}, 5}, {{0.99, 0.59}, 7}, {{0.25, 0.1}, 1},
            {{-0.5, 2.0}, 4}, {{1.0, 0.0}, 3},  {{7.0, -3.0}, 3},  {{0.74, 0.31}, 6}};
  for (size_t k = 0; k < sizeof(at) / sizeof(at[0]); k++)
    if (partition_cell_of(p, at[k].x) != at[k].cell)
      fail_msg("(%g, %g): cell %d, expected %d", at[k].x[0], at[k].x[1],
               (int)partition_cell_of(p, at[k].x), (int)at[k].cell);
  OK(partition_measure_imbalance(&s.part, &s));
  assert_close(s.part.imbalance, 1.0, 0);
  done();
  /* no reach: 64 cells per axis */
  make(1.0, 0.6, PETSC_FALSE, 0.0);
  OK(partition_setup(&s.part, &s));
  assert_int_equal(s.part.nc[0], 64);
  assert_int_equal(s.part.nc[1], 64);
  done();
  /* a width that does not divide L: the edge grows past it */
  make(1.0, 1.0, PETSC_FALSE, 0.3);
  OK(partition_setup(&s.part, &s));
  assert_int_equal(s.part.nc[0], 3);
  assert_true(s.part.edge[0] >= 0.3);
  assert_close(s.part.edge[0], 1.0 / 3.0, 1e-16);
  done();
}

static void test_options(void **state) {
  (void)state;
  make(1.0, 1.0, PETSC_FALSE, 0.1);
  OK(partition_set_from_options(&s.part, &s));
  assert_close(s.part.imbalance_max, 1.2, 0);
  assert_int_equal(s.part.interval, 100);
  OK(PetscOptionsInsertString(NULL, "-partition_imbalance 1.05 -partition_interval 7"));
  OK(partition_set_from_options(&s.part, &s));
  assert_close(s.part.imbalance_max, 1.05, 0);
  assert_int_equal(s.part.interval, 7);
  OK(PetscOptionsClear(NULL));
  OK(PetscOptionsInsertString(NULL, "-partition_imbalance 0.9"));
  assert_int_equal(partition_set_from_options(&s.part, &s), PETSC_ERR_ARG_OUTOFRANGE);
  OK(PetscOptionsClear(NULL));
  OK(PetscOptionsInsertString(NULL, "-partition_interval -1"));
  assert_int_equal(partition_set_from_options(&s.part, &s), PETSC_ERR_ARG_OUTOFRANGE);
  OK(PetscOptionsClear(NULL));
  options_forget();
  OK(particles_destroy(&s.ps));
}

/* Part r's cells connected through the 8-neighbour cell graph (wrapping along x when periodic). */
static PetscBool connected(const partition *p, PetscMPIInt r, PetscBool periodic_x) {
  PetscInt stack[256], n = 0, seen = 0, total = 0;
  char visited[256] = {0};
  for (PetscInt c = 0; c < p->n_cells; c++)
    total += p->owner[c] == r;
  for (PetscInt c = 0; c < p->n_cells && !n; c++)
    if (p->owner[c] == r) {
      stack[n++] = c;
      visited[c] = 1;
    }
  while (n) {
    const PetscInt c = stack[--n], cx = c % p->nc[0], cy = c / p->nc[0];
    seen++;
    for (int dy = -1; dy <= 1; dy++)
      for (int dx = -1; dx <= 1; dx++) {
        PetscInt ux = cx + dx;
        const PetscInt uy = cy + dy;
        if (periodic_x)
          ux = (ux + p->nc[0]) % p->nc[0];
        if (ux < 0 || ux >= p->nc[0] || uy < 0 || uy >= p->nc[1])
          continue;
        const PetscInt u = uy * p->nc[0] + ux;
        if (p->owner[u] == r && !visited[u]) {
          visited[u] = 1;
          stack[n++] = u;
        }
      }
  }
  return seen == total ? PETSC_TRUE : PETSC_FALSE;
}

static void check_frontier(const partition *p, PetscBool periodic_x) {
  for (PetscInt c = 0; c < p->n_cells; c++) {
    const PetscInt cx = c % p->nc[0], cy = c / p->nc[0];
    char want = 0;
    if (p->owner[c] == 0)
      for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
          const PetscInt ux = cx + dx, uy = cy + dy;
          if (uy < 0 || uy >= p->nc[1])
            continue;
          if (ux < 0 || ux >= p->nc[0]) {
            want |= periodic_x ? 1 : 0;
            continue;
          }
          want |= p->owner[uy * p->nc[0] + ux] != 0;
        }
    if ((p->frontier[c] != 0) != (want != 0))
      fail_msg("cell %d (%d, %d) of part %d: frontier %d, expected %d", (int)c, (int)cx, (int)cy,
               (int)p->owner[c], p->frontier[c], want);
  }
}

static void run_two_parts(PetscBool periodic_x, PetscBool left_heavy) {
  make(1.0, 1.0, periodic_x, 0.125); /* 8 x 8 cells */
  for (int iy = 0; iy < 32; iy++)
    for (int ix = 0; ix < 32; ix++) {
      const double x = (ix + 0.5) / 32.0, y = (iy + 0.5) / 32.0;
      add(x, y);
      if (left_heavy && x < 0.5)
        add(x, y + 0.25 / 32.0); /* twice the particles on the left */
    }
  OK(partition_setup(&s.part, &s));
  s.size = 2; /* METIS into two parts, on this process (rank 0) */
  OK(partition_compute(&s.part, &s));
  const partition *p = &s.part;
  assert_int_equal(p->n_cells, 64);
  assert_int_equal(p->n_repartitions, 1);
  assert_true(p->edge_cut > 0);
  PetscInt64 work[2] = {0, 0}, cells[2] = {0, 0};
  PetscInt per_cell[64] = {0};
  for (PetscInt i = 0; i < s.ps.n_owned; i++)
    per_cell[partition_cell_of(p, s.ps.x[i])] += 16;
  for (PetscInt c = 0; c < 64; c++) {
    assert_true(p->owner[c] == 0 || p->owner[c] == 1);
    work[p->owner[c]] += per_cell[c] + 1;
    cells[p->owner[c]]++;
  }
  const double half = 0.5 * (double)(work[0] + work[1]);
  if (fabs((double)work[0] - half) > 0.1 * half)
    fail_msg("work %lld and %lld: not balanced", (long long)work[0], (long long)work[1]);
  assert_true(cells[0] > 0 && cells[1] > 0);
  assert_true(connected(p, 0, periodic_x) && connected(p, 1, periodic_x));
  check_frontier(p, periodic_x);
  /* fixed seed: the same counts, the same owners */
  PetscMPIInt first[64];
  for (PetscInt c = 0; c < 64; c++)
    first[c] = p->owner[c];
  OK(partition_compute(&s.part, &s));
  for (PetscInt c = 0; c < 64; c++)
    assert_int_equal(p->owner[c], first[c]);
  s.size = 1;
  done();
}

static void test_two_parts(void **state) {
  (void)state;
  run_two_parts(PETSC_FALSE, PETSC_FALSE);
  run_two_parts(PETSC_TRUE, PETSC_FALSE);
  run_two_parts(PETSC_FALSE, PETSC_TRUE);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_grid),
      cmocka_unit_test(test_options),
      cmocka_unit_test(test_two_parts),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
