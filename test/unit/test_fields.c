/* The field table (src/core/fields.c). Proves, against the table written out
 * by hand here (what each per-particle array is and where it must go):
 *   - the always-present rows, in order, with their width, element type and
 *     flags (migrate / ghost / checkpoint / output), and that each row's offset
 *     is the address of the struct member of that name;
 *   - row bytes = width x element size;
 *   - optional rows are absent until enabled, then appear once, in table
 *     order; enabling twice is harmless; an unknown name, an always-present
 *     row, and a new row once particles exist (frozen) are errors;
 *   - fields_reset goes back to the always-present rows. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/fields.h"
#include "dmhs/particles.h"

#define M FIELD_MIGRATE
#define G FIELD_GHOST
#define C FIELD_CHECKPOINT
#define O FIELD_OUTPUT
#define F FIELD_FIXED

typedef struct {
  const char *name;
  int width;
  field_kind kind;
  unsigned flags;
  size_t offset;
} expected_row;

/* The always-present rows. v_est is derived in the first half step (not
 * checkpointed, not written); v_visc (optional: with walls) is rebuilt by the wall
 * pass before every force sweep (ghosts only); drho and p are the SPH module's (optional,
 * below); x_build is internal (not written); gid, type, mass (and the
 * optional body and marks) change only at a neighbour build (F: ghosts keep their build's
 * copy, no refresh between builds sends them). */
static const expected_row base[] = {
    {"gid", 1, FIELD_INT64, M | G | C | O | F, offsetof(particles, gid)},
    {"type", 1, FIELD_INT, M | G | C | O | F, offsetof(particles, type)},
    {"x", 2, FIELD_REAL, M | G | C | O, offsetof(particles, x)},
    {"v", 2, FIELD_REAL, M | G | C | O, offsetof(particles, v)},
    {"v_est", 2, FIELD_REAL, M | G, offsetof(particles, v_est)},
    {"a", 2, FIELD_REAL, M | C | O, offsetof(particles, a)},
    {"x_build", 2, FIELD_REAL, M | C, offsetof(particles, x_build)},
    {"mass", 1, FIELD_REAL, M | G | C | O | F, offsetof(particles, mass)},
    {"rho", 1, FIELD_REAL, M | G | C | O, offsetof(particles, rho)},
};
#define N_BASE (sizeof(base) / sizeof(base[0]))

static int setup(void **state) {
  if (unit_petsc_setup(state))
    return -1;
  fields_reset();
  return 0;
}

static int reset(void **state) {
  (void)state;
  fields_reset();
  return 0;
}

static void test_base_rows(void **state) {
  (void)state;
  size_t n;
  const field_desc *t = fields_table(&n);
  assert_int_equal(n, N_BASE);
  for (size_t k = 0; k < N_BASE; k++) {
    assert_string_equal(t[k].name, base[k].name);
    assert_int_equal(t[k].width, base[k].width);
    assert_int_equal(t[k].kind, base[k].kind);
    if (t[k].flags != base[k].flags)
      fail_msg("field %s: flags 0x%x, expected 0x%x", t[k].name, t[k].flags, base[k].flags);
    assert_int_equal(t[k].offset, base[k].offset);
    assert_non_null(t[k].unit);
    assert_true(fields_find(base[k].name) == &t[k]);
    assert_true(fields_enabled(base[k].name));
  }
  assert_null(fields_find("no_such_field"));
  assert_false(fields_enabled("no_such_field"));
}

static void test_row_bytes_and_member(void **state) {
  (void)state;
  particles ps;
  memset(&ps, 0, sizeof(ps));
  assert_int_equal(fields_row_bytes(fields_find("x")), 2 * sizeof(double));
  assert_int_equal(fields_row_bytes(fields_find("rho")), sizeof(double));
  assert_int_equal(fields_row_bytes(fields_find("gid")), sizeof(PetscInt64));
  assert_int_equal(fields_row_bytes(fields_find("type")), sizeof(PetscInt));
  /* fields_member is the address of the pointer member itself */
  assert_true(fields_member(&ps, fields_find("x")) == (void **)&ps.x);
  assert_true(fields_member(&ps, fields_find("v_est")) == (void **)&ps.v_est);
  OK(fields_enable("p"));
  assert_true(fields_member(&ps, fields_find("p")) == (void **)&ps.p);
  assert_true(fields_member(&ps, fields_find("gid")) == (void **)&ps.gid);
}

static void test_optional_rows(void **state) {
  (void)state;
  size_t n;
  assert_null(fields_find("body"));
  assert_false(fields_enabled("a_hold"));
  OK(fields_enable("a_hold"));
  OK(fields_enable("body"));
  OK(fields_enable("body")); /* twice: harmless */
  const field_desc *t = fields_table(&n);
  assert_int_equal(n, N_BASE + 2);
  /* in table order (body before a_hold), after the always-present rows */
  assert_string_equal(t[N_BASE].name, "body");
  assert_string_equal(t[N_BASE + 1].name, "a_hold");
  assert_int_equal(t[N_BASE].flags, M | G | C | O | F | FIELD_OPTIONAL);
  assert_int_equal(t[N_BASE].kind, FIELD_INT);
  assert_int_equal(t[N_BASE].offset, offsetof(particles, body));
  assert_int_equal(t[N_BASE + 1].flags, M | C | FIELD_OPTIONAL);
  assert_int_equal(t[N_BASE + 1].width, 2);
  assert_int_equal(t[N_BASE + 1].offset, offsetof(particles, a_hold));
  /* a diagnostic row: written, never migrated nor saved */
  OK(fields_enable("shear_rate"));
  const field_desc *f = fields_find("shear_rate");
  assert_non_null(f);
  assert_int_equal(f->flags, O | FIELD_OPTIONAL);
  t = fields_table(&n);
  assert_int_equal(n, N_BASE + 3);
  assert_string_equal(t[N_BASE + 1].name, "shear_rate");
  /* the optional initial position and named marks (load, segment, tracer) */
  OK(fields_enable("x0"));
  OK(fields_enable("tracer"));
  assert_int_equal(fields_find("x0")->flags, M | C | O | FIELD_OPTIONAL);
  assert_int_equal(fields_find("tracer")->flags, M | C | O | F | FIELD_OPTIONAL);
  assert_int_equal(fields_find("tracer")->kind, FIELD_INT);
  assert_null(fields_find("load"));
  assert_null(fields_find("tag")); /* gone: one field per use */
  t = fields_table(&n);
  assert_int_equal(n, N_BASE + 5);
  /* the SPH module's: the density rate (p is recomputed before use, so it is not migrated) */
  assert_null(fields_find("p"));
  OK(fields_enable("drho"));
  OK(fields_enable("p"));
  assert_int_equal(fields_find("drho")->flags, M | C | O | FIELD_OPTIONAL);
  assert_int_equal(fields_find("p")->flags, G | C | O | FIELD_OPTIONAL);
  t = fields_table(&n);
  assert_int_equal(n, N_BASE + 7);
  size_t at_rho = 0; /* table order: right after rho */
  while (at_rho + 2 < n && strcmp(t[at_rho].name, "rho"))
    at_rho++;
  assert_string_equal(t[at_rho + 1].name, "drho");
  assert_string_equal(t[at_rho + 2].name, "p");
  fields_reset();
  t = fields_table(&n);
  assert_int_equal(n, N_BASE);
  assert_null(fields_find("body"));
}

static void test_enable_errors(void **state) {
  (void)state;
  assert_int_equal(fields_enable("no_such_field"), PETSC_ERR_ARG_UNKNOWN_TYPE);
  assert_int_equal(fields_enable("x"), PETSC_ERR_ARG_WRONG);
  OK(fields_enable("body"));
  fields_freeze(PETSC_TRUE); /* particles exist */
  assert_int_equal(fields_enable("side"), PETSC_ERR_ORDER);
  assert_null(fields_find("side"));
  OK(fields_enable("body")); /* already there: still harmless */
  fields_freeze(PETSC_FALSE);
  OK(fields_enable("side"));
  assert_non_null(fields_find("side"));
}

/* A store allocates the table's rows: reserving freezes the table. */
static void test_reserve_freezes(void **state) {
  (void)state;
  particles ps;
  OK(particles_create(&ps));
  OK(particles_reserve(&ps, 4));
  assert_int_equal(fields_enable("body"), PETSC_ERR_ORDER);
  OK(particles_destroy(&ps));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_base_rows, reset, reset),
      cmocka_unit_test_setup_teardown(test_row_bytes_and_member, reset, reset),
      cmocka_unit_test_setup_teardown(test_optional_rows, reset, reset),
      cmocka_unit_test_setup_teardown(test_enable_errors, reset, reset),
      cmocka_unit_test_setup_teardown(test_reserve_freezes, reset, reset),
  };
  return cmocka_run_group_tests(tests, setup, unit_petsc_teardown);
}
