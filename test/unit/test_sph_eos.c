/* Equations of state (src/physics/sph_eos.h). Proves:
 *   - Tait: p(rho0) = 0 and p = B((rho/rho0)^7 - 1), B = c0^2 rho0 / 7, at several densities;
 *   - linear p = c0^2 rho and linear-shifted p = c0^2 (rho - rho0);
 *   - sph_eos_density inverts sph_eos_pressure for every kind (round trip to 1e-12 relative);
 *   - Tait tension below -B gives a small positive density, not NaN;
 *   - the background pressure p_b shifts p by exactly p_b for every kind (p_b = 0: unchanged),
 *     and sph_eos_density_bg inverts sph_eos_pressure_bg;
 *   - sph_eos_compute (the pass over the rows, vectorised per kind) gives every non-wall row,
 *     owned or ghost, exactly sph_eos_pressure_bg of its density, and leaves walls' p as they
 *     were, for every kind. */
#include "unit_common.h"
#include "dmhs/sim.h"
#include "physics/sph_eos.h"
#include "physics/sph_force.h"

static const double rho0 = 998.2, c0 = 13.5;
static const double rhos[] = {900.0, 990.0, 998.2, 1003.7, 1050.0, 1200.0};
#define N_RHO (sizeof(rhos) / sizeof(rhos[0]))

static void test_tait(void **state) {
  (void)state;
  const double B = c0 * c0 * rho0 / 7.0;
  assert_close(sph_eos_pressure(SPH_EOS_TAIT, rho0, rho0, c0), 0.0, 1e-12 * B);
  for (size_t i = 0; i < N_RHO; i++) {
    const double expect = B * (pow(rhos[i] / rho0, 7.0) - 1.0);
    assert_close(sph_eos_pressure(SPH_EOS_TAIT, rhos[i], rho0, c0), expect, 1e-12 * B);
  }
  /* small compressions: dp/drho = c0^2 at rho0 */
  const double d = 1e-4 * rho0;
  const double p_plus = sph_eos_pressure(SPH_EOS_TAIT, rho0 + d, rho0, c0);
  const double p_minus = sph_eos_pressure(SPH_EOS_TAIT, rho0 - d, rho0, c0);
  const double slope = (p_plus - p_minus) / (2.0 * d);
  assert_close(slope, c0 * c0, 1e-6 * c0 * c0);
}

static void test_linear(void **state) {
  (void)state;
  for (size_t i = 0; i < N_RHO; i++) {
    const double tol = 1e-12 * c0 * c0 * rho0;
    assert_close(sph_eos_pressure(SPH_EOS_LINEAR, rhos[i], rho0, c0), c0 * c0 * rhos[i], tol);
    assert_close(sph_eos_pressure(SPH_EOS_LINEAR_SHIFTED, rhos[i], rho0, c0),
                 c0 * c0 * (rhos[i] - rho0), tol);
  }
  assert_true(sph_eos_pressure(SPH_EOS_LINEAR_SHIFTED, rho0, rho0, c0) == 0.0);
}

static void test_density_inverts_pressure(void **state) {
  (void)state;
  const sph_eos_kind kinds[] = {SPH_EOS_TAIT, SPH_EOS_LINEAR, SPH_EOS_LINEAR_SHIFTED};
  for (int k = 0; k < 3; k++)
    for (size_t i = 0; i < N_RHO; i++) {
      const double p = sph_eos_pressure(kinds[k], rhos[i], rho0, c0);
      const double back = sph_eos_density(kinds[k], p, rho0, c0);
      if (fabs(back - rhos[i]) > 1e-12 * rhos[i])
        fail_msg("eos %d: rho %.17g -> p %.17g -> rho %.17g", k, rhos[i], p, back);
    }
}

static void test_tait_tension_clamped(void **state) {
  (void)state;
  const double B = c0 * c0 * rho0 / 7.0;
  const double rho = sph_eos_density(SPH_EOS_TAIT, -2.0 * B, rho0, c0);
  assert_true(isfinite(rho) && rho > 0.0 && rho < 0.1 * rho0);
}

static void test_background_pressure(void **state) {
  (void)state;
  const sph_eos_kind kinds[] = {SPH_EOS_TAIT, SPH_EOS_LINEAR, SPH_EOS_LINEAR_SHIFTED};
  for (size_t k = 0; k < 3; k++)
    for (size_t i = 0; i < N_RHO; i++) {
      const double p = sph_eos_pressure(kinds[k], rhos[i], rho0, c0);
      sph_params off = {.rho0 = rho0, .c0 = c0, .eos = kinds[k]}, on = off;
      on.p_background = 250.0;
      assert_true(sph_eos_pressure_bg(&off, rhos[i]) == p);
      assert_close(sph_eos_pressure_bg(&on, rhos[i]), p + 250.0, 1e-12 * (fabs(p) + 250.0));
      assert_close(sph_eos_density_bg(&on, sph_eos_pressure_bg(&on, rhos[i])), rhos[i],
                   1e-12 * rhos[i]);
    }
}

static void test_eos_pass(void **state) {
  (void)state;
  sim s;
  OK(PetscMemzero(&s, sizeof(s)));
  fields_reset();
  OK(unit_enable_sph_fields());
  OK(particles_create(&s.ps));
  const double x[2] = {0, 0}, v[2] = {0, 0};
  const PetscInt n = 37; /* not a multiple of a vector's width */
  for (PetscInt i = 0; i < n; i++)
    OK(particles_add_owned(&s.ps, i, (particle_type)(i % PTYPE_COUNT), x, v, 1.0,
                           rhos[i % N_RHO] + 0.01 * (double)i, NULL));
  s.ps.n_owned = 30; /* the last rows stand for ghosts, which the pass covers too */
  s.ps.n_ghost = n - 30;
  const sph_eos_kind kinds[] = {SPH_EOS_TAIT, SPH_EOS_LINEAR, SPH_EOS_LINEAR_SHIFTED};
  for (size_t k = 0; k < 3; k++) {
    const sph_params sp = {.rho0 = rho0, .c0 = c0, .eos = kinds[k], .p_background = 250.0};
    for (PetscInt i = 0; i < n; i++)
      s.ps.p[i] = -7.0;
    OK(sph_eos_compute(&s, &sp));
    for (PetscInt i = 0; i < n; i++) {
      const double want = s.ps.type[i] == PTYPE_WALL ? -7.0 : sph_eos_pressure_bg(&sp, s.ps.rho[i]);
      if (!(s.ps.p[i] == want))
        fail_msg("eos %d, row %d (type %d): p = %.17g, want %.17g", (int)k, (int)i,
                 (int)s.ps.type[i], s.ps.p[i], want);
    }
  }
  OK(particles_destroy(&s.ps));
  fields_reset();
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_tait),
      cmocka_unit_test(test_eos_pass),
      cmocka_unit_test(test_linear),
      cmocka_unit_test(test_density_inverts_pressure),
      cmocka_unit_test(test_tait_tension_clamped),
      cmocka_unit_test(test_background_pressure),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
