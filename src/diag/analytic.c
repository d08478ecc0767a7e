/* Series solutions of start-up Poiseuille, Couette and Womersley flow (formulas in
 * analytic.h). A term is dropped, and the sum ends, once its bound falls below 1e-16
 * of the flow's speed scale (steady peak, plate speed, g0/w): later terms are smaller
 * still. */
#include <math.h>
#include <complex.h>
#include "dmhs/analytic.h"

#define ANALYTIC_MAX_TERMS 200000

double analytic_poiseuille(double y, double t, double F, double nu, double l) {
  const double peak = F * l * l / (8.0 * nu);
  const double decay = M_PI * M_PI * nu * t / (l * l);
  double sum = 0.0;
  for (int n = 0; n < ANALYTIC_MAX_TERMS; n++) {
    const double k = 2.0 * n + 1.0;
    const double bound =
        4.0 * F * l * l / (nu * M_PI * M_PI * M_PI * k * k * k) * exp(-k * k * decay);
    if (bound < 1e-16 * fabs(peak))
      break;
    sum += bound * sin(k * M_PI * y / l);
  }
  return F / (2.0 * nu) * y * (l - y) - sum;
}

double analytic_couette(double y, double t, double V, double nu, double l) {
  const double decay = M_PI * M_PI * nu * t / (l * l);
  double sum = 0.0;
  for (int n = 1; n < ANALYTIC_MAX_TERMS; n++) {
    const double bound = 2.0 * V / (n * M_PI) * exp(-(double)n * n * decay);
    if (fabs(bound) < 1e-16 * fabs(V))
      break;
    sum += bound * ((n & 1) ? -1.0 : 1.0) * sin(n * M_PI * y / l);
  }
  return V * y / l + sum;
}

/* Womersley start-up. With s = y - a and c_n = 4 (-1)^n/((2n+1) pi), the cosine series
 * of 1 on |s| < a is sum c_n cos(lam_n s) = 1, so (-nu d2/ds2 of both sides, zero at
 * s = +-a):
 *   P = sum c_n cos(lam_n s)/beta_n   = (a^2 - s^2)/(2 nu)                  (-nu P'' = 1)
 *   Q = sum c_n cos(lam_n s)/beta_n^2 = (a^2 - s^2)(5 a^2 - s^2)/(24 nu^2)  (-nu Q'' = P)
 * and b_n = g0 [sin(wt)/beta_n - w cos(wt)/beta_n^2 + w r_n] with
 *   r_n = [exp(-beta_n t) - w sin(wt)/beta_n]/(beta_n^2 + w^2)
 *         + w^2 cos(wt)/(beta_n^2 (beta_n^2 + w^2)),
 * so v_x = g0 [sin(wt) P - w cos(wt) Q + w sum c_n cos(lam_n s) r_n]. Once exp(-beta_n t)
 * is small, r_n falls as beta_n^-3: ~170 terms at a sqrt(w/nu) = 2.76 (~1400 at t = 0). */
double analytic_womersley(double y, double t, double g0, double w, double nu, double l) {
  if (t <= 0)
    return 0.0; /* at rest until the drive starts */
  const double a = 0.5 * l, s = y - a, a2 = a * a, s2 = s * s, w2 = w * w;
  const double P = (a2 - s2) / (2.0 * nu), Q = (a2 - s2) * (5.0 * a2 - s2) / (24.0 * nu * nu);
  const double sn = sin(w * t), cs = cos(w * t), scale = 1.0 / w; /* of v_x/g0 */
  double sum = 0.0;
  for (int n = 0; n < ANALYTIC_MAX_TERMS; n++) {
    const double k = 2.0 * n + 1.0, lam = k * M_PI / l, beta = nu * lam * lam;
    const double c = ((n & 1) ? -4.0 : 4.0) / (k * M_PI), d = beta * beta + w2, e = exp(-beta * t);
    const double bound = fabs(c) * w * (e + w / beta + w2 / (beta * beta)) / d;
    if (bound < 1e-16 * scale)
      break;
    const double r = (e - w * sn / beta) / d + w2 * cs / (beta * beta * d);
    sum += c * cos(lam * s) * r;
  }
  return g0 * (sn * P - w * cs * Q + w * sum);
}

/* 1 - cosh(kappa s)/cosh(kappa a) for |s| <= a, without overflow at large kappa a:
 * cosh(z1)/cosh(z2) = exp(z1 - z2) (1 + exp(-2 z1))/(1 + exp(-2 z2)), Re z >= 0. */
static double complex womersley_shape(double s, double a, double w, double nu) {
  const double q = sqrt(0.5 * w / nu);
  const double complex kappa = CMPLX(q, q); /* sqrt(i w/nu) */
  s = fabs(s);
  const double complex ratio =
      cexp(kappa * (s - a)) * (1.0 + cexp(-2.0 * kappa * s)) / (1.0 + cexp(-2.0 * kappa * a));
  return 1.0 - ratio;
}

double analytic_womersley_periodic(double y, double t, double g0, double w, double nu, double l) {
  const double a = 0.5 * l;
  const double complex amplitude = (g0 / I) / (I * w) * womersley_shape(y - a, a, w, nu);
  return creal(amplitude * cexp(I * w * t));
}

double analytic_womersley_amplitude(double g0, double w, double nu, double l) {
  return cabs(g0 / (I * w) * womersley_shape(0.0, 0.5 * l, w, nu));
}

double analytic_peristaltic_flux(double a, double b, double c) {
  const double phi = b / a;
  return 2.0 * a * c * 3.0 * phi * phi / (2.0 + phi * phi);
}

double analytic_peristaltic_pressure_range(double a, double b, double lambda, double c, double mu) {
  enum { N = 4096 };
  const double dx = lambda / N;
  double mean_h2 = 0, mean_h3 = 0;
  for (int k = 0; k < N; k++) {
    const double h = a + b * sin(2.0 * M_PI * (k + 0.5) / N);
    mean_h2 += 1.0 / (h * h * N);
    mean_h3 += 1.0 / (h * h * h * N);
  }
  const double q = -2.0 * c * mean_h2 / mean_h3;
  double p = 0, p_min = 0, p_max = 0;
  for (int k = 0; k < N; k++) {
    const double h = a + b * sin(2.0 * M_PI * (k + 0.5) / N);
    p += -3.0 * mu * (q + 2.0 * c * h) / (2.0 * h * h * h) * dx;
    p_min = p < p_min ? p : p_min;
    p_max = p > p_max ? p : p_max;
  }
  return p_max - p_min;
}
