/* The struct-of-arrays particle store (src/core/particles.c). Proves:
 *   - particles_add_owned appends rows with the given values and the derived
 *     ones (x0 = x_build = x, v_est = v_visc = v, a = drho = p = tracer = 0), and
 *     returns the new row's index;
 *   - growing one particle at a time keeps every earlier row of every field,
 *     capacity stays >= the rows in use and grows geometrically (at most
 *     about log_1.5 of the count reallocations), and every row of the field
 *     table is allocated while rows not enabled stay NULL;
 *   - particles_reserve below the capacity changes nothing;
 *   - adding with ghosts present is refused;
 *   - removing by compaction (particles_copy_row(kept, i, all), as migration
 *     and partitioning do) leaves exactly the kept particles, whole;
 *   - particles_copy_row with FIELD_GHOST copies the ghost fields only;
 *   - particles_count_type counts owned rows only;
 *   - particles_retire makes a row a wall at rest at the given place and
 *     density (with the optional rows of -sph_density_predict zeroed), and
 *     leaves gid, mass and the other rows alone;
 *   - pack / unpack of the FIELD_MIGRATE fields round-trips every field
 *     bitwise, adds the shift to x only, and packs exactly the sum of the
 *     row sizes per particle. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/particles.h"
#include "dmhs/fields.h"

/* the optional rows these tests read too: the initial position and a named mark */
static int reset(void **state) {
  (void)state;
  fields_reset();
  OK(fields_enable("x0"));
  OK(fields_enable("tracer"));
  OK(fields_enable("v_visc"));
  OK(unit_enable_sph_fields());
  return 0;
}

/* Deterministic values of particle number k, distinct per field. */
static void values(PetscInt k, double x[2], double v[2], double *m, double *rho) {
  x[0] = 0.5 + 0.001 * (double)k;
  x[1] = -0.25 - 0.002 * (double)k;
  v[0] = 1.0 + (double)k;
  v[1] = -3.0 * (double)k;
  *m = 1e-3 * (double)(k + 1);
  *rho = 1000.0 + (double)k;
}

static PetscInt64 gid_of(PetscInt k) {
  return 1000000007LL * (PetscInt64)k + 3;
}
static particle_type type_of(PetscInt k) {
  return (particle_type)(k % PTYPE_COUNT);
}

static void add(particles *ps, PetscInt k) {
  double x[2], v[2], m, rho;
  PetscInt idx = -1;
  values(k, x, v, &m, &rho);
  const PetscInt before = ps->n_owned;
  OK(particles_add_owned(ps, gid_of(k), type_of(k), x, v, m, rho, &idx));
  assert_int_equal(idx, before);
  assert_int_equal(ps->n_owned, before + 1);
}

/* Row i holds particle k as particles_add_owned left it. */
static void check_row(const particles *ps, PetscInt i, PetscInt k) {
  double x[2], v[2], m, rho;
  values(k, x, v, &m, &rho);
  if (ps->gid[i] != gid_of(k))
    fail_msg("row %d: gid %lld, expected %lld", (int)i, (long long)ps->gid[i],
             (long long)gid_of(k));
  assert_int_equal(ps->type[i], type_of(k));
  assert_int_equal(ps->tracer[i], 0);
  for (int d = 0; d < 2; d++) {
    assert_true(ps->x[i][d] == x[d]);
    assert_true(ps->x0[i][d] == x[d]);
    assert_true(ps->x_build[i][d] == x[d]);
    assert_true(ps->v[i][d] == v[d]);
    assert_true(ps->v_est[i][d] == v[d]);
    assert_true(ps->v_visc[i][d] == v[d]);
    assert_true(ps->a[i][d] == 0.0);
  }
  assert_true(ps->mass[i] == m);
  assert_true(ps->rho[i] == rho);
  assert_true(ps->drho[i] == 0.0);
  assert_true(ps->p[i] == 0.0);
}

static void test_add_and_grow(void **state) {
  (void)state;
  particles ps;
  OK(particles_create(&ps));
  assert_int_equal(ps.n_owned, 0);
  assert_int_equal(ps.capacity, 0);
  assert_null(ps.x);
  const PetscInt n = 5000;
  int reallocations = 0;
  PetscInt cap = ps.capacity;
  for (PetscInt k = 0; k < n; k++) {
    add(&ps, k);
    assert_true(ps.capacity >= ps.n_owned);
    if (ps.capacity != cap) {
      reallocations++;
      /* at least 1.5x (or the first 16 rows) each time */
      assert_true(ps.capacity >= cap + cap / 2 + 16);
      cap = ps.capacity;
    }
  }
  /* 16, 40, 76, ... : 1.5x per reallocation reaches 5000 in fewer than 16 */
  assert_true(reallocations >= 2 && reallocations < 16);
  for (PetscInt i = 0; i < n; i++)
    check_row(&ps, i, i);
  /* every active row of the table is allocated; rows not enabled are not */
  size_t nf;
  const field_desc *t = fields_table(&nf);
  for (size_t f = 0; f < nf; f++)
    assert_non_null(*fields_member(&ps, &t[f]));
  assert_null(ps.body);
  assert_null(ps.a_hold);
  assert_null(ps.shear_rate);
  /* reserve below the capacity: nothing moves */
  double(*x)[2] = ps.x;
  const PetscInt c = ps.capacity;
  OK(particles_reserve(&ps, 10));
  assert_true(ps.x == x && ps.capacity == c);
  /* above: contents kept */
  OK(particles_reserve(&ps, 3 * c));
  assert_true(ps.capacity >= 3 * c);
  for (PetscInt i = 0; i < n; i += 97)
    check_row(&ps, i, i);
  OK(particles_destroy(&ps));
  assert_null(ps.x);
  assert_int_equal(ps.capacity, 0);
  assert_int_equal(ps.n_owned, 0);
}

static void test_optional_row_allocated(void **state) {
  (void)state;
  particles ps;
  OK(fields_enable("body"));
  OK(particles_create(&ps));
  for (PetscInt k = 0; k < 40; k++) {
    add(&ps, k);
    ps.body[k] = (PetscInt)(7 * k + 1);
  }
  for (PetscInt k = 0; k < 40; k++)
    assert_int_equal(ps.body[k], 7 * k + 1);
  assert_null(ps.a_hold);
  OK(particles_destroy(&ps));
}

static void test_add_with_ghosts_refused(void **state) {
  (void)state;
  particles ps;
  OK(particles_create(&ps));
  add(&ps, 0);
  ps.n_ghost = 1;
  const double x[2] = {0, 0}, v[2] = {0, 0};
  assert_int_equal(particles_add_owned(&ps, 9, PTYPE_FLUID, x, v, 1, 1, NULL),
                   PETSC_ERR_ARG_WRONGSTATE);
  assert_int_equal(ps.n_owned, 1);
  ps.n_ghost = 0;
  OK(particles_destroy(&ps));
}

/* Removal as migrate.c and partition.c do it: compact the rows that stay. */
static void test_remove_by_compaction(void **state) {
  (void)state;
  particles ps;
  OK(fields_enable("body"));
  OK(particles_create(&ps));
  const PetscInt n = 101;
  for (PetscInt k = 0; k < n; k++) {
    add(&ps, k);
    ps.body[k] = (PetscInt)k;
  }
  /* remove every particle whose number is divisible by 3 */
  PetscInt kept = 0;
  for (PetscInt i = 0; i < ps.n_owned; i++) {
    if (i % 3 == 0)
      continue;
    if (kept != i)
      particles_copy_row(&ps, kept, i, ~0u);
    kept++;
  }
  ps.n_owned = kept;
  assert_int_equal(kept, n - 34); /* 0, 3, ..., 99: 34 removed */
  PetscInt i = 0;
  for (PetscInt k = 0; k < n; k++) {
    if (k % 3 == 0)
      continue;
    check_row(&ps, i, k);
    assert_int_equal(ps.body[i], k);
    i++;
  }
  OK(particles_destroy(&ps));
}

static void test_copy_row_by_flags(void **state) {
  (void)state;
  particles ps;
  OK(particles_create(&ps));
  add(&ps, 1);
  add(&ps, 2);
  ps.p[0] = 5.0;
  ps.a[0][0] = 7.0;
  ps.drho[0] = 9.0;
  ps.x0[0][1] = 11.0;
  particles_copy_row(&ps, 1, 0, FIELD_GHOST);
  double x[2], v[2], m, rho, x2[2], v2[2], m2, rho2;
  values(1, x, v, &m, &rho);
  values(2, x2, v2, &m2, &rho2);
  /* ghost fields: copied */
  assert_true(ps.gid[1] == gid_of(1) && ps.type[1] == (PetscInt)type_of(1));
  assert_true(ps.x[1][0] == x[0] && ps.x[1][1] == x[1]);
  assert_true(ps.v[1][0] == v[0] && ps.v_est[1][1] == v[1] && ps.v_visc[1][0] == v[0]);
  assert_true(ps.mass[1] == m && ps.rho[1] == rho && ps.p[1] == 5.0);
  /* not ghost fields (a, x0, x_build, drho): row 1 keeps its own */
  assert_true(ps.a[1][0] == 0.0 && ps.drho[1] == 0.0);
  assert_true(ps.x0[1][0] == x2[0] && ps.x0[1][1] == x2[1]);
  assert_true(ps.x_build[1][1] == x2[1]);
  OK(particles_destroy(&ps));
}

static void test_count_type(void **state) {
  (void)state;
  particles ps;
  OK(particles_create(&ps));
  for (PetscInt k = 0; k < 10; k++)
    add(&ps, k); /* types k % 4: 0 1 2 3 0 1 2 3 0 1 */
  assert_int_equal(particles_count_type(&ps, PTYPE_FLUID), 3);
  assert_int_equal(particles_count_type(&ps, PTYPE_WALL), 3);
  assert_int_equal(particles_count_type(&ps, PTYPE_SOLID), 2);
  assert_int_equal(particles_count_type(&ps, PTYPE_CLOT), 2);
  /* ghost rows are not counted */
  ps.n_owned = 9;
  assert_int_equal(particles_count_type(&ps, PTYPE_WALL), 2);
  ps.n_owned = 10;
  OK(particles_destroy(&ps));
}

static void test_pack_unpack(void **state) {
  (void)state;
  particles a, b;
  const field_desc *f[32];
  OK(fields_enable("a_hold"));
  OK(particles_create(&a));
  OK(particles_create(&b));
  for (PetscInt k = 0; k < 8; k++) {
    add(&a, k);
    a.a[k][0] = 0.5 * (double)k;
    a.drho[k] = -(double)k;
    a.tracer[k] = (PetscInt)(100 + k);
    a.a_hold[k][1] = 3.0 + (double)k;
    a.p[k] = 1e5; /* not a migrate field */
  }
  const int nf = particles_select_fields(FIELD_MIGRATE, f, 32);
  /* gid type x v v_est a x0 x_build mass rho drho a_hold tracer */
  assert_int_equal(nf, 13);
  const size_t want =
      sizeof(PetscInt64) + 2 * sizeof(PetscInt) + (6 * 2 + 3) * sizeof(double) + 2 * sizeof(double);
  assert_int_equal(particles_packed_bytes(f, nf), want);
  /* a short output array: the first fields only */
  const field_desc *g[3];
  assert_int_equal(particles_select_fields(FIELD_MIGRATE, g, 3), 3);
  assert_string_equal(g[2]->name, "x");

  const PetscInt rows[3] = {5, 0, 6};
  const double shift[3][2] = {{1.0, 0.0}, {0.0, -2.0}, {0.25, 0.5}};
  char *buf;
  OK(PetscMalloc1(3 * want, &buf));
  particles_pack(&a, f, nf, rows, 3, shift, buf);
  OK(particles_reserve(&b, 5));
  particles_unpack(&b, f, nf, 2, 3, buf);
  for (PetscInt e = 0; e < 3; e++) {
    const PetscInt s = rows[e], d = 2 + e;
    assert_true(b.gid[d] == a.gid[s] && b.type[d] == a.type[s] && b.tracer[d] == a.tracer[s]);
    for (int c = 0; c < 2; c++) {
      assert_true(b.x[d][c] == a.x[s][c] + shift[e][c]);
      assert_true(b.v[d][c] == a.v[s][c] && b.v_est[d][c] == a.v_est[s][c]);
      assert_true(b.a[d][c] == a.a[s][c] && b.x0[d][c] == a.x0[s][c]);
      assert_true(b.x_build[d][c] == a.x_build[s][c] && b.a_hold[d][c] == a.a_hold[s][c]);
    }
    assert_true(b.mass[d] == a.mass[s] && b.rho[d] == a.rho[s] && b.drho[d] == a.drho[s]);
    assert_true(b.p[d] == 0.0); /* not packed */
  }
  /* without a shift, x is copied as it is */
  particles_pack(&a, f, nf, rows, 3, NULL, buf);
  particles_unpack(&b, f, nf, 0, 3, buf);
  for (PetscInt e = 0; e < 3; e++)
    assert_true(b.x[e][0] == a.x[rows[e]][0] && b.x[e][1] == a.x[rows[e]][1]);
  OK(PetscFree(buf));
  OK(particles_destroy(&a));
  OK(particles_destroy(&b));
}

static void test_retire(void **state) {
  (void)state;
  particles ps;
  OK(fields_enable("drho_prev"));
  OK(particles_create(&ps));
  for (PetscInt k = 0; k < 3; k++)
    add(&ps, 4 * k); /* three fluid particles */
  for (PetscInt i = 0; i < 3; i++) {
    ps.a[i][0] = ps.a[i][1] = 5.0;
    ps.drho[i] = ps.drho_prev[i] = 7.0;
  }
  const double slot[2] = {3.5, -1.25};
  const double m1 = ps.mass[1];
  particles_retire(&ps, 1, slot, 998.0);
  assert_int_equal(ps.type[1], PTYPE_WALL);
  assert_true(ps.x[1][0] == 3.5 && ps.x[1][1] == -1.25);
  for (int d = 0; d < 2; d++)
    assert_true(ps.v[1][d] == 0 && ps.v_est[1][d] == 0 && ps.v_visc[1][d] == 0 && ps.a[1][d] == 0);
  assert_true(ps.rho[1] == 998.0 && ps.drho[1] == 0 && ps.drho_prev[1] == 0);
  assert_true(ps.mass[1] == m1 && ps.gid[1] == gid_of(4));
  /* the others untouched */
  assert_int_equal(ps.type[0], PTYPE_FLUID);
  assert_int_equal(ps.type[2], PTYPE_FLUID);
  assert_true(ps.a[0][0] == 5.0 && ps.drho[2] == 7.0 && ps.drho_prev[0] == 7.0);
  OK(particles_destroy(&ps));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_add_and_grow, reset, reset),
      cmocka_unit_test_setup_teardown(test_optional_row_allocated, reset, reset),
      cmocka_unit_test_setup_teardown(test_add_with_ghosts_refused, reset, reset),
      cmocka_unit_test_setup_teardown(test_remove_by_compaction, reset, reset),
      cmocka_unit_test_setup_teardown(test_copy_row_by_flags, reset, reset),
      cmocka_unit_test_setup_teardown(test_count_type, reset, reset),
      cmocka_unit_test_setup_teardown(test_pack_unpack, reset, reset),
      cmocka_unit_test_setup_teardown(test_retire, reset, reset),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
