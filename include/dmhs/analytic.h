/* Series solutions of the start-up channel flows (doc/cases.md), walls at y = 0 and y = l.
 *   Poiseuille (body force F from rest):
 *     v_x = F/(2 nu) y (l - y)
 *           - sum_{n>=0} 4 F l^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y/l) exp(-(2n+1)^2 pi^2 nu t/l^2)
 *   Couette (upper plate at V from t = 0):
 *     v_x = V y/l + sum_{n>=1} 2 V (-1)^n/(n pi) sin(n pi y/l) exp(-n^2 pi^2 nu t/l^2)
 *   Womersley start-up (body force g0 sin(w t) from rest at t = 0, a = l/2):
 *     v_x = sum_{n>=0} 4 (-1)^n/((2n+1) pi) cos(lam_n (y - a)) b_n(t),
 *     lam_n = (2n+1) pi/l, beta_n = nu lam_n^2,
 *     b_n(t) = g0 [beta_n sin wt - w cos wt + w exp(-beta_n t)]/(beta_n^2 + w^2).
 *   Its steady-periodic limit (t -> infinity), kappa = sqrt(i w/nu):
 *     v_x = Re[(g0/i)/(i w) (1 - cosh(kappa (y - a))/cosh(kappa a)) e^{i w t}]
 *   (g0/i is the complex amplitude of g0 sin wt = Re[(g0/i) e^{i w t}]), with the
 *   centreline amplitude |g0/(i w) (1 - 1/cosh(kappa a))|.
 * Terms are summed until they no longer change the result (at most 200000). */
#ifndef DMHS_ANALYTIC_H
#define DMHS_ANALYTIC_H

double analytic_poiseuille(double y, double t, double F, double nu, double l);
double analytic_couette(double y, double t, double V, double nu, double l);
/* The Womersley start-up series above (0 for t <= 0, before the drive starts); w > 0.
 * Summed as g0 [sin(wt) P(y) - w cos(wt) Q(y)] + the remaining series, where P and Q
 * are the closed forms of sum c_n cos(lam_n (y-a))/beta_n^k (k = 1, 2): the same
 * series, rearranged so that its terms fall as (2n+1)^-7 instead of (2n+1)^-3. */
double analytic_womersley(double y, double t, double g0, double w, double nu, double l);
/* The steady-periodic limit above. */
double analytic_womersley_periodic(double y, double t, double g0, double w, double nu, double l);
/* Its centreline amplitude |g0/(i w) (1 - 1/cosh(kappa a))| [m/s]: the speed scale of
 * the pulsatile channel's error (a pulsatile flow passes through zero). */
double analytic_womersley_amplitude(double g0, double w, double nu, double l);

/* Peristaltic pumping at long wavelength and low Reynolds number (Shapiro, Jaffrin &
 * Weinberg 1969): walls y = +-h, h = a + b sin(2 pi (x - c t)/lambda), no pressure rise
 * over a wavelength. In the wave frame the flow is steady lubrication flow between walls
 * moving at -c, with volume flux q = -2 c <h^-2>/<h^-3> (per unit depth, <.> the mean
 * over a wavelength); the lab frame's time-mean flux is
 *   Q = q + 2 c a = 2 a c 3 phi^2/(2 + phi^2),  phi = b/a   [m^2/s]. */
double analytic_peristaltic_flux(double a, double b, double c);
/* The range max p - min p [Pa] of that flow's pressure along the wavelength, of
 *   dp/dx = -3 mu (q + 2 c h)/(2 h^3),  mu = rho0 nu
 * (midpoint quadrature of 4096 points): the scale of the liquid's density deviation,
 * which sets the peristaltic scene's sound speed. */
double analytic_peristaltic_pressure_range(double a, double b, double lambda, double c, double mu);

#endif
