/* Migration on one rank (src/core/migrate.c; the exchange between ranks is
 * unit_migrate_mpi). Proves:
 *   - migrate_particles wraps positions into the box along periodic
 *     directions (by whole periods, also several), drops the ghosts, and
 *     keeps every particle and its other fields;
 *   - a particle outside the box along a closed direction stops the run with
 *     PETSC_ERR_FP and a message naming its gid, the step and the position;
 *     one exactly on the closed boundary does not;
 *   - -debug_migration: the first check takes the reference; a reordering
 *     passes; a lost particle, a duplicated one, and one whose gid changed
 *     (count right, set wrong) each fail naming what happened;
 *   - without -debug_migration nothing is checked. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/migrate.h"

static char message[1024];

/* Keeps the first message of an error (PETSC_ERROR_INITIAL) and returns its code. */
static PetscErrorCode capture(MPI_Comm comm, int line, const char *func, const char *file,
                              PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx) {
  (void)comm, (void)line, (void)func, (void)file, (void)ctx;
  if (p == PETSC_ERROR_INITIAL)
    snprintf(message, sizeof(message), "%s", mess ? mess : "");
  return n;
}

static void assert_contains(const char *text, const char *part) {
  if (!strstr(text, part))
    fail_msg("'%s' does not contain '%s'", text, part);
}

static sim s;

static void make(PetscInt n) {
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  s.size = 1;
  s.dom = (domain){.lo = {0.0, -1.0}, .hi = {2.0, 1.0}, .periodic = {PETSC_TRUE, PETSC_FALSE}};
  fields_reset();
  OK(particles_create(&s.ps));
  for (PetscInt k = 0; k < n; k++) {
    const double x[2] = {0.01 + 0.1 * (double)k, -0.9 + 0.05 * (double)k}, v[2] = {(double)k, 0.0};
    OK(particles_add_owned(&s.ps, 10 * k + 1, PTYPE_FLUID, x, v, 1.0 + (double)k, 1000.0, NULL));
  }
}

static void test_wrap(void **state) {
  (void)state;
  make(6);
  s.ps.x[0][0] = 2.25; /* one period right */
  s.ps.x[1][0] = -0.5; /* one left */
  s.ps.x[2][0] = 6.75; /* three right */
  s.ps.x[3][0] = 2.0;  /* exactly hi: lo */
  s.ps.x[4][1] = 1.0;  /* on the closed boundary: inside */
  s.ps.n_ghost = 0;
  OK(migrate_particles(&s));
  assert_int_equal(s.ps.n_owned, 6);
  assert_int_equal(s.ps.n_ghost, 0);
  assert_close(s.ps.x[0][0], 0.25, 1e-15);
  assert_close(s.ps.x[1][0], 1.5, 1e-15);
  assert_close(s.ps.x[2][0], 0.75, 1e-15);
  assert_close(s.ps.x[3][0], 0.0, 0);
  assert_close(s.ps.x[4][1], 1.0, 0);
  /* y is closed: never wrapped; other fields untouched */
  for (PetscInt k = 0; k < 6; k++) {
    assert_true(s.ps.gid[k] == 10 * k + 1);
    assert_true(s.ps.v[k][0] == (double)k && s.ps.mass[k] == 1.0 + (double)k);
    if (k != 4)
      assert_close(s.ps.x[k][1], -0.9 + 0.05 * (double)k, 0);
  }
  OK(particles_destroy(&s.ps));
}

static void test_escape(void **state) {
  (void)state;
  make(4);
  s.step = 17;
  s.t = 0.0017;
  s.ps.x[2][1] = 1.0 + 1e-9; /* gid 21 above the closed top */
  message[0] = 0;
  OK(PetscPushErrorHandler(capture, NULL));
  const PetscErrorCode err = migrate_particles(&s);
  OK(PetscPopErrorHandler());
  assert_int_equal(err, PETSC_ERR_FP);
  assert_contains(message, "particle gid 21 escaped the domain at step 17");
  assert_contains(message, "outside [0., 2.] x [-1., 1.]" /* PETSc prints %g of 0 as "0." */);
  /* below the bottom, as well */
  s.ps.x[2][1] = 0.0;
  s.ps.x[3][1] = -1.5;
  OK(PetscPushErrorHandler(capture, NULL));
  assert_int_equal(migrate_particles(&s), PETSC_ERR_FP);
  OK(PetscPopErrorHandler());
  assert_contains(message, "particle gid 31 escaped");
  OK(particles_destroy(&s.ps));
}

static PetscErrorCode check(void) {
  OK(PetscPushErrorHandler(capture, NULL));
  message[0] = 0;
  const PetscErrorCode err = migrate_check_ids(&s.mig, &s);
  OK(PetscPopErrorHandler());
  return err;
}

static void test_debug_migration(void **state) {
  (void)state;
  make(8);
  OK(PetscOptionsInsertString(NULL, "-debug_migration"));
  OK(migrate_set_from_options(&s.mig, &s));
  OK(PetscOptionsClear(NULL));
  options_forget();
  assert_true(s.mig.enabled);
  OK(check()); /* the reference */
  assert_true(s.mig.have_reference);
  assert_true(s.mig.reference[0] == 8);
  assert_true(s.mig.reference[1] == 1 + 11 + 21 + 31 + 41 + 51 + 61 + 71);
  /* another order: the same set */
  particles_copy_row(&s.ps, 8, 0, ~0u); /* row 8 is spare capacity */
  particles_copy_row(&s.ps, 0, 5, ~0u);
  particles_copy_row(&s.ps, 5, 8, ~0u);
  OK(check());
  /* lost: the last particle */
  s.step = 3;
  s.ps.n_owned = 7;
  assert_int_equal(check(), PETSC_ERR_PLIB);
  assert_contains(message, "step 3: 7 particles over the ranks, expected 8 (particles were lost)");
  /* duplicated: one more copy of row 0 */
  s.ps.n_owned = 8;
  OK(particles_reserve(&s.ps, 9));
  particles_copy_row(&s.ps, 8, 0, ~0u);
  s.ps.n_owned = 9;
  assert_int_equal(check(), PETSC_ERR_PLIB);
  assert_contains(message, "9 particles over the ranks, expected 8 (particles were duplicated)");
  /* right count, wrong set: gid 71 replaced by a copy of gid 1 */
  s.ps.n_owned = 8;
  PetscInt i1 = -1, i71 = -1;
  for (PetscInt i = 0; i < 8; i++) {
    if (s.ps.gid[i] == 1)
      i1 = i;
    if (s.ps.gid[i] == 71)
      i71 = i;
  }
  assert_true(i1 >= 0 && i71 >= 0);
  s.ps.gid[i71] = 1;
  assert_int_equal(check(), PETSC_ERR_PLIB);
  assert_contains(message, "the particle count is right but the set of global ids changed");
  s.ps.gid[i71] = 71;
  OK(check());
  /* the same count and sum of gids (1 + 71 = 31 + 41), another set: the hash sum sees it */
  s.ps.gid[i1] = 31;
  s.ps.gid[i71] = 41;
  assert_int_equal(check(), PETSC_ERR_PLIB);
  assert_contains(message, "set of global ids changed");
  OK(particles_destroy(&s.ps));
}

static void test_debug_migration_off(void **state) {
  (void)state;
  make(3);
  OK(migrate_set_from_options(&s.mig, &s));
  options_forget();
  assert_false(s.mig.enabled);
  OK(check());
  s.ps.n_owned = 1; /* not checked */
  OK(check());
  assert_false(s.mig.have_reference);
  OK(particles_destroy(&s.ps));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_wrap),
      cmocka_unit_test(test_escape),
      cmocka_unit_test(test_debug_migration),
      cmocka_unit_test(test_debug_migration_off),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
