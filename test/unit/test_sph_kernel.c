/* SPH kernels (src/physics/sph_kernel.h), for Lucy, cubic B-spline and Wendland
 * C2 in 1, 2 and 3 dimensions. Proves:
 *   - the normalisation: the integral of W over its support is 1 (to 1e-9);
 *   - dW/dr agrees with a central finite difference of W at 100 radii in (0, h);
 *   - W = dW/dr = 0 at and beyond the support radius h;
 *   - the cubic spline's pieces meet at the inner knot r = h/2 (W and dW/dr). */
#include "unit_common.h"
#include "physics/sph_kernel.h"

static const sph_kernel_kind kinds[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
static const char *const kind_name[] = {"lucy", "cubic", "wendland"};
static const double h = 0.37; /* not 1, so that a wrong power of h shows */

static double W(sph_kernel_kind k, int dim, double r) {
  double w = 0, dw = 0;
  sph_kernel_eval(k, dim, sph_kernel_norm(k, dim, h), 1.0 / h, r, &w, &dw);
  return w;
}

/* Measure of the sphere of radius r in dim dimensions times W: the radial integrand. */
static double radial(sph_kernel_kind k, int dim, double r) {
  const double shell = dim == 1 ? 2.0 : dim == 2 ? 2.0 * M_PI * r : 4.0 * M_PI * r * r;
  return shell * W(k, dim, r);
}

/* Composite Simpson on [a, b] with n (even) intervals. */
static double simpson(sph_kernel_kind k, int dim, double a, double b, int n) {
  const double dr = (b - a) / n;
  double sum = radial(k, dim, a) + radial(k, dim, b);
  for (int i = 1; i < n; i++)
    sum += (i % 2 ? 4.0 : 2.0) * radial(k, dim, a + i * dr);
  return sum * dr / 3.0;
}

static void test_normalisation(void **state) {
  (void)state;
  for (int ik = 0; ik < 3; ik++)
    for (int dim = 1; dim <= 3; dim++) {
      /* split at the cubic's knot so every piece is a polynomial */
      const double integral =
          simpson(kinds[ik], dim, 0.0, 0.5 * h, 4000) + simpson(kinds[ik], dim, 0.5 * h, h, 4000);
      if (fabs(integral - 1.0) > 1e-9)
        fail_msg("%s %dD: integral of W = %.15g, expected 1", kind_name[ik], dim, integral);
    }
}

static void test_gradient_matches_finite_difference(void **state) {
  (void)state;
  const double d = 1e-6 * h;
  for (int ik = 0; ik < 3; ik++)
    for (int dim = 1; dim <= 3; dim++) {
      const double norm = sph_kernel_norm(kinds[ik], dim, h);
      for (int i = 0; i < 100; i++) {
        const double r = (i + 0.5) / 100.0 * h; /* never within d of the knot h/2 */
        double w = 0, dwdr = 0;
        sph_kernel_eval(kinds[ik], dim, norm, 1.0 / h, r, &w, &dwdr);
        const double fd = (W(kinds[ik], dim, r + d) - W(kinds[ik], dim, r - d)) / (2.0 * d);
        if (fabs(dwdr - fd) > 1e-7 * norm / h)
          fail_msg("%s %dD r/h = %g: dW/dr = %.12g, finite difference %.12g", kind_name[ik], dim,
                   r / h, dwdr, fd);
      }
    }
}

static void test_zero_outside_support(void **state) {
  (void)state;
  const double radii[] = {h, nextafter(h, 2.0 * h), 1.5 * h, 10.0 * h};
  for (int ik = 0; ik < 3; ik++)
    for (int dim = 1; dim <= 3; dim++)
      for (size_t i = 0; i < sizeof(radii) / sizeof(radii[0]); i++) {
        double w = -1, dwdr = -1;
        sph_kernel_eval(kinds[ik], dim, sph_kernel_norm(kinds[ik], dim, h), 1.0 / h, radii[i], &w,
                        &dwdr);
        assert_true(w == 0.0 && dwdr == 0.0);
      }
  /* ... and positive, decreasing just inside it */
  for (int ik = 0; ik < 3; ik++)
    for (int dim = 1; dim <= 3; dim++) {
      double w = 0, dwdr = 0;
      sph_kernel_eval(kinds[ik], dim, sph_kernel_norm(kinds[ik], dim, h), 1.0 / h, 0.99 * h, &w,
                      &dwdr);
      assert_true(w > 0.0 && dwdr < 0.0);
    }
}

static void test_cubic_continuous_at_knot(void **state) {
  (void)state;
  const double knot = 0.5 * h, e = 1e-10 * h;
  for (int dim = 1; dim <= 3; dim++) {
    const double norm = sph_kernel_norm(SPH_KERNEL_CUBIC, dim, h);
    double w_in = 0, dw_in = 0, w_out = 0, dw_out = 0;
    sph_kernel_eval(SPH_KERNEL_CUBIC, dim, norm, 1.0 / h, knot - e, &w_in, &dw_in);
    sph_kernel_eval(SPH_KERNEL_CUBIC, dim, norm, 1.0 / h, knot + e, &w_out, &dw_out);
    assert_close(w_in, w_out, 1e-8 * norm);
    assert_close(dw_in, dw_out, 1e-8 * norm / h);
    /* at the knot u = 1 both pieces give W = norm / 4 */
    assert_close(w_in, 0.25 * norm, 1e-8 * norm);
  }
}

/* sph_kernel_grad, the pair loops' (dW/dr)/r without a division where the kernel allows,
 * equals dW/dr / r of sph_kernel_eval to round-off, over the support. */
static void test_grad_factor(void **state) {
  (void)state;
  const sph_kernel_kind kinds[] = {SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND};
  const double h = 2.5e-4;
  for (int ik = 0; ik < 3; ik++)
    for (int dim = 1; dim <= 3; dim++) {
      const double norm = sph_kernel_norm(kinds[ik], dim, h), inv_h = 1.0 / h;
      const double gn = sph_kernel_grad_norm(kinds[ik], dim, norm, inv_h);
      for (double f = 0.01; f < 1.0; f += 0.0131) {
        const double r = f * h;
        double w = 0, dwdr = 0;
        sph_kernel_eval(kinds[ik], dim, norm, inv_h, r, &w, &dwdr);
        const double grad = sph_kernel_grad(kinds[ik], dim, gn, norm, inv_h, r);
        assert_true(fabs(grad - dwdr / r) <= 1e-13 * fabs(dwdr / r) + 1e-300);
        assert_true(grad < 0);
      }
    }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_normalisation),
      cmocka_unit_test(test_gradient_matches_finite_difference),
      cmocka_unit_test(test_zero_outside_support),
      cmocka_unit_test(test_cubic_continuous_at_knot),
      cmocka_unit_test(test_grad_factor),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
