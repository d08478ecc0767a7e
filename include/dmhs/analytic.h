/* Series solutions of the start-up channel flows (SPEC 4.1), walls at y = 0 and y = l.
 *   Poiseuille (body force F from rest):
 *     v_x = F/(2 nu) y (l - y)
 *           - sum_{n>=0} 4 F l^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y/l) exp(-(2n+1)^2 pi^2 nu t/l^2)
 *   Couette (upper plate at V from t = 0):
 *     v_x = V y/l + sum_{n>=1} 2 V (-1)^n/(n pi) sin(n pi y/l) exp(-n^2 pi^2 nu t/l^2)
 * Terms are summed until they no longer change the result (at most 200000). */
#ifndef DMHS_ANALYTIC_H
#define DMHS_ANALYTIC_H

double analytic_poiseuille(double y, double t, double F, double nu, double l);
double analytic_couette(double y, double t, double V, double nu, double l);

#endif
