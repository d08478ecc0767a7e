/* Series solutions of start-up Poiseuille and Couette flow (formulas in analytic.h).
 * A term is dropped, and the sum ends, once its bound falls below 1e-16 of the
 * steady peak speed: later terms are smaller still. */
#include <math.h>
#include "dmhs/analytic.h"

#define ANALYTIC_MAX_TERMS 200000

double analytic_poiseuille(double y, double t, double F, double nu, double l) {
  const double peak = F * l * l / (8.0 * nu);
  const double decay = M_PI * M_PI * nu * t / (l * l);
  double sum = 0.0;
  for (int n = 0; n < ANALYTIC_MAX_TERMS; n++) {
    const double k = 2.0 * n + 1.0;
    const double bound = 4.0 * F * l * l / (nu * M_PI * M_PI * M_PI * k * k * k) * exp(-k * k * decay);
    if (bound < 1e-16 * fabs(peak)) break;
    sum += bound * sin(k * M_PI * y / l);
  }
  return F / (2.0 * nu) * y * (l - y) - sum;
}

double analytic_couette(double y, double t, double V, double nu, double l) {
  const double decay = M_PI * M_PI * nu * t / (l * l);
  double sum = 0.0;
  for (int n = 1; n < ANALYTIC_MAX_TERMS; n++) {
    const double bound = 2.0 * V / (n * M_PI) * exp(-(double)n * n * decay);
    if (fabs(bound) < 1e-16 * fabs(V)) break;
    sum += bound * ((n & 1) ? -1.0 : 1.0) * sin(n * M_PI * y / l);
  }
  return V * y / l + sum;
}
