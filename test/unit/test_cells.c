/* Ghosts (src/core/halo.c) and the pair list (src/core/cells.c) against a
 * brute-force O(N^2) minimum-image search. For random particles in a box periodic
 * in both directions, periodic in x only (closed y, with wall particles), and a
 * box only slightly larger than 2 * cutoff, it proves that:
 *   - every pair is listed once, with i < j, at least one owned, not two walls,
 *     and closer than the cutoff;
 *   - ghost rows carry their source's gid and sit exactly one shift away from it;
 *   - mapping each pair to the gids of its particles, every owned particle's
 *     multiset of neighbour gids equals the brute-force one (all other owned
 *     particles within the cutoff at minimum image, walls not pairing with walls), so the
 *     candidate runs, cut by x and by the height above a row, lose no partner;
 *   - the runs lie inside the half stencil's cells and are shorter than them;
 *   - the segments of consecutive rows cover the cell order exactly, each all owned or all
 *     ghost, and none could be joined to the one before it. */
#include <stdlib.h>
#include "unit_common.h"
#include "dmhs/cells.h"
#include "dmhs/halo.h"

static int cmp_i64(const void *a, const void *b) {
  const PetscInt64 x = *(const PetscInt64 *)a, y = *(const PetscInt64 *)b;
  return (x > y) - (x < y);
}

/* cells.h's segments: positions [seg_pos[s], seg_pos[s + 1]) hold rows seg_row[s], +1, ...,
 * all owned or all ghost, and as long as they can be */
static void check_segments(const cells *c, PetscInt n_owned, PetscInt rows) {
  assert_true(c->n_seg >= 1 && c->n_seg <= rows);
  assert_int_equal(c->seg_pos[0], 0);
  assert_int_equal(c->seg_pos[c->n_seg], rows);
  for (PetscInt s = 0; s < c->n_seg; s++) {
    const PetscInt first = c->seg_pos[s], last = c->seg_pos[s + 1];
    assert_true(last > first);
    for (PetscInt k = first; k < last; k++)
      assert_int_equal(c->order[k], c->seg_row[s] + (k - first));
    assert_true(c->seg_row[s] >= n_owned || c->seg_row[s] + (last - first) <= n_owned);
    if (s > 0)
      assert_true(c->order[first] != c->order[first - 1] + 1 || c->order[first] == n_owned);
  }
}

typedef struct {
  const char *name;
  double L[2];
  PetscBool periodic[2];
  double cutoff;
  PetscInt n;
  double wall_fraction; /* share of particles made walls */
  double lattice;       /* > 0: a square lattice of this spacing from lo (points on lo) instead */
} cells_case;

static void run_case(const cells_case *cc, uint64_t seed) {
  unit_rng g = {seed};
  const domain d = {.lo = {-0.3, 1.0},
                    .hi = {-0.3 + cc->L[0], 1.0 + cc->L[1]},
                    .periodic = {cc->periodic[0], cc->periodic[1]}};
  const double cut = cc->cutoff, cut2 = cut * cut;
  OK(domain_check_ghost_width(&d, cut));
  particles ps;
  halo hal;
  cells cel;
  OK(particles_create(&ps));
  const PetscInt nx = cc->lattice > 0 ? (PetscInt)round(cc->L[0] / cc->lattice) : 0;
  for (PetscInt i = 0; i < cc->n; i++) {
    double x[2] = {unit_range(&g, d.lo[0], d.hi[0]), unit_range(&g, d.lo[1], d.hi[1])};
    const double v[2] = {0, 0};
    if (nx) {
      x[0] = d.lo[0] + (double)(i % nx) * cc->lattice;
      x[1] = d.lo[1] + (double)(i / nx) * cc->lattice;
    }
    const particle_type t = unit_uniform(&g) < cc->wall_fraction ? PTYPE_WALL : PTYPE_FLUID;
    OK(particles_add_owned(&ps, 7 * i + 3, t, x, v, 1.0, 1.0, NULL));
  }
  OK(halo_create(&hal, cut, PETSC_COMM_SELF));
  OK(halo_build(&hal, &d, NULL, &ps)); /* one rank: no partition needed */
  OK(cells_create(&cel));
  const double lo[2] = {d.lo[0] - cut, d.lo[1] - cut}, hi[2] = {d.hi[0] + cut, d.hi[1] + cut};
  OK(cells_build_pairs(&cel, &ps, lo, hi, cut));

  const PetscInt n = ps.n_owned, rows = n + ps.n_ghost;
  assert_int_equal(ps.n_ghost, hal.n);
  check_segments(&cel, n, rows);
  for (PetscInt gh = 0; gh < hal.n; gh++) {
    const PetscInt row = n + gh, src = hal.source[gh];
    assert_true(src >= 0 && src < n);
    assert_true(ps.gid[row] == ps.gid[src] && ps.type[row] == ps.type[src]);
    assert_true(ps.x[row][0] == ps.x[src][0] + hal.shift[gh][0]);
    assert_true(ps.x[row][1] == ps.x[src][1] + hal.shift[gh][1]);
  }

  /* neighbour gid lists from the pair list, per owned row */
  PetscInt *count, *fill;
  PetscInt64 *nb;
  OK(PetscCalloc2(n + 1, &count, n + 1, &fill));
  for (PetscInt k = 0; k < cel.n_pairs; k++) {
    const PetscInt i = cel.pair_i[k], j = cel.pair_j[k];
    assert_true(i >= 0 && i < j && j < rows && i < n);
    assert_false(ps.type[i] == PTYPE_WALL && ps.type[j] == PTYPE_WALL);
    const double dx = ps.x[i][0] - ps.x[j][0], dy = ps.x[i][1] - ps.x[j][1];
    assert_true(dx * dx + dy * dy < cut2);
    count[i + 1]++;
    if (j < n)
      count[j + 1]++;
  }
  for (PetscInt i = 0; i < n; i++)
    count[i + 1] += count[i];
  OK(PetscMalloc1(count[n] + 1, &nb));
  OK(PetscArraycpy(fill, count, n));
  for (PetscInt k = 0; k < cel.n_pairs; k++) {
    const PetscInt i = cel.pair_i[k], j = cel.pair_j[k];
    nb[fill[i]++] = ps.gid[j];
    if (j < n)
      nb[fill[j]++] = ps.gid[i];
  }

  /* brute force per owned particle */
  PetscInt64 *ref;
  OK(PetscMalloc1(n, &ref));
  PetscInt total = 0;
  for (PetscInt i = 0; i < n; i++) {
    PetscInt m = 0;
    for (PetscInt j = 0; j < n; j++) {
      if (j == i || (ps.type[i] == PTYPE_WALL && ps.type[j] == PTYPE_WALL))
        continue;
      double r[2] = {ps.x[i][0] - ps.x[j][0], ps.x[i][1] - ps.x[j][1]};
      domain_min_image(&d, r);
      if (r[0] * r[0] + r[1] * r[1] < cut2)
        ref[m++] = ps.gid[j];
    }
    PetscInt64 *got = nb + count[i];
    const PetscInt n_got = count[i + 1] - count[i];
    qsort(ref, (size_t)m, sizeof(*ref), cmp_i64);
    qsort(got, (size_t)n_got, sizeof(*got), cmp_i64);
    if (n_got != m)
      fail_msg("%s: particle gid %lld has %d listed neighbours, brute force %d", cc->name,
               (long long)ps.gid[i], (int)n_got, (int)m);
    for (PetscInt k = 0; k < m; k++)
      if (got[k] != ref[k])
        fail_msg("%s: particle gid %lld: neighbour sets differ", cc->name, (long long)ps.gid[i]);
    total += m;
  }
  assert_true(total > cc->n); /* the case is not vacuous */
  /* the cut runs lie inside the half stencil's cells (the upper run may be empty: a row
   * near the bottom of its cell has nothing within the cutoff above it) and are shorter
   * than them where the cells hold more than a cutoff's width of rows (the complete list
   * above proves that no partner was cut) */
  PetscInt64 cut_len = 0, full_len = 0;
  const PetscInt n0 = cel.n[0], n1 = cel.n[1];
  for (PetscInt cy = 0; cy < n1; cy++)
    for (PetscInt cx = 0; cx < n0; cx++) {
      const PetscInt cell = cy * n0 + cx, up = (cy + 1) * n0 + cx;
      const PetscInt end1 = cx + 1 < n0 ? cel.start[cell + 2] : cel.start[cell + 1];
      const PetscInt f2 = cy + 1 < n1 ? cel.start[up + PetscMax(cx - 1, 0) - cx] : 0;
      const PetscInt l2 = cy + 1 < n1 ? cel.start[up + PetscMin(cx + 1, n0 - 1) - cx + 1] : 0;
      for (PetscInt a = cel.start[cell]; a < cel.start[cell + 1]; a++) {
        assert_true(cel.run_end1[a] >= a + 1 && cel.run_end1[a] <= end1);
        assert_true(cel.run_first2[a] <= cel.run_last2[a]);
        if (cel.run_first2[a] < cel.run_last2[a])
          assert_true(cel.run_first2[a] >= f2 && cel.run_last2[a] <= l2);
        cut_len += (cel.run_end1[a] - a - 1) + (cel.run_last2[a] - cel.run_first2[a]);
        full_len += (end1 - a - 1) + (l2 - f2);
      }
    }
  if (cc->n >= 400)
    assert_true(cut_len < full_len);
  OK(PetscFree(ref));
  OK(PetscFree(nb));
  OK(PetscFree2(count, fill));
  OK(cells_destroy(&cel));
  OK(halo_destroy(&hal));
  OK(particles_destroy(&ps));
}

static void test_periodic_both(void **state) {
  (void)state;
  const cells_case c = {"periodic x,y", {1.0, 0.7}, {PETSC_TRUE, PETSC_TRUE}, 0.093, 600, 0.0, 0};
  for (uint64_t seed = 1; seed <= 3; seed++)
    run_case(&c, seed);
}

static void test_periodic_x_closed_y(void **state) {
  (void)state;
  const cells_case c = {
      "periodic x, closed y", {0.8, 0.6}, {PETSC_TRUE, PETSC_FALSE}, 0.071, 500, 0.3, 0};
  for (uint64_t seed = 11; seed <= 13; seed++)
    run_case(&c, seed);
}

static void test_box_just_over_twice_cutoff(void **state) {
  (void)state;
  const cells_case c = {
      "tight periodic", {2.001 * 0.1, 2.0005 * 0.1}, {PETSC_TRUE, PETSC_TRUE}, 0.1, 60, 0.0, 0};
  for (uint64_t seed = 21; seed <= 30; seed++)
    run_case(&c, seed);
  const cells_case c2 = {
      "tight x, closed y", {2.001 * 0.1, 0.35}, {PETSC_TRUE, PETSC_FALSE}, 0.1, 80, 0.2, 0};
  for (uint64_t seed = 31; seed <= 40; seed++)
    run_case(&c2, seed);
}

static void test_closed_box(void **state) {
  (void)state;
  const cells_case c = {"closed", {0.55, 0.43}, {PETSC_FALSE, PETSC_FALSE}, 0.05, 400, 0.1, 0};
  run_case(&c, 77);
}

/* Points exactly on the lower boundaries; spacing incommensurate with the cutoff
 * (lattice distances^2 / dx^2 are integers, never (0.07/0.03)^2). */
static void test_lattice(void **state) {
  (void)state;
  const cells_case c = {
      "lattice periodic", {0.6, 0.45}, {PETSC_TRUE, PETSC_TRUE}, 0.07, 20 * 15, 0.0, 0.03};
  run_case(&c, 5);
  const cells_case c2 = {
      "lattice x periodic", {0.6, 0.45}, {PETSC_TRUE, PETSC_FALSE}, 0.07, 20 * 16, 0.0, 0.03};
  run_case(&c2, 6);
}

/* cells_sort_owned_rows: afterwards the rows run by (cell, gid); every particle keeps
 * its fields (each row's x, v, mass and type still belong to its gid); sorting again
 * changes nothing; and the pair build then lists the owned rows in row order. */
static void test_sort_owned_rows(void **state) {
  (void)state;
  unit_rng g = {99};
  const domain d = {.lo = {0.0, 0.0}, .hi = {1.0, 0.7}, .periodic = {PETSC_TRUE, PETSC_TRUE}};
  const double cut = 0.05;
  const double lo[2] = {-cut, -cut}, hi[2] = {1.0 + cut, 0.7 + cut};
  particles ps;
  OK(particles_create(&ps));
  const PetscInt n = 600;
  for (PetscInt i = 0; i < n; i++) {
    const double x[2] = {unit_range(&g, 0.0, 1.0), unit_range(&g, 0.0, 0.7)};
    /* fields that identify the particle: v = (gid, -gid), mass = 1 + gid */
    const PetscInt64 gid = 1000 - 3 * i;
    const double v[2] = {(double)gid, -(double)gid};
    OK(particles_add_owned(&ps, gid, i % 5 ? PTYPE_FLUID : PTYPE_WALL, x, v, 1.0 + (double)gid, 1.0,
                           NULL));
  }
  OK(cells_sort_owned_rows(&ps, lo, hi, cut));
  PetscInt grid[2];
  double inv[2];
  cells_grid(lo, hi, cut, grid, inv);
  for (PetscInt i = 0; i < n; i++) {
    assert_true(ps.v[i][0] == (double)ps.gid[i] && ps.v[i][1] == -(double)ps.gid[i]);
    assert_true(ps.mass[i] == 1.0 + (double)ps.gid[i]);
    assert_int_equal(ps.type[i], ((1000 - ps.gid[i]) / 3) % 5 ? PTYPE_FLUID : PTYPE_WALL);
    if (i > 0) {
      const PetscInt c0 = cells_locate(lo, inv, grid, ps.x[i - 1]),
                     c1 = cells_locate(lo, inv, grid, ps.x[i]);
      assert_true(c0 < c1 ||
                  (c0 == c1 && (ps.x[i - 1][0] < ps.x[i][0] ||
                                (ps.x[i - 1][0] == ps.x[i][0] && ps.gid[i - 1] < ps.gid[i]))));
    }
  }
  double x_first = ps.x[0][0];
  OK(cells_sort_owned_rows(&ps, lo, hi, cut));
  assert_true(ps.x[0][0] == x_first);
  halo hal;
  cells cel;
  OK(halo_create(&hal, cut, PETSC_COMM_SELF));
  OK(halo_build(&hal, &d, NULL, &ps));
  OK(cells_create(&cel));
  OK(cells_build_pairs(&cel, &ps, lo, hi, cut));
  PetscInt last = -1;
  for (PetscInt k = 0; k < n + ps.n_ghost; k++)
    if (cel.order[k] < n) {
      assert_true(cel.order[k] > last);
      last = cel.order[k];
    }
  assert_int_equal(last, n - 1);
  OK(cells_destroy(&cel));
  OK(halo_destroy(&hal));
  OK(particles_destroy(&ps));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_periodic_both),
      cmocka_unit_test(test_periodic_x_closed_y),
      cmocka_unit_test(test_box_just_over_twice_cutoff),
      cmocka_unit_test(test_closed_box),
      cmocka_unit_test(test_lattice),
      cmocka_unit_test(test_sort_owned_rows),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
