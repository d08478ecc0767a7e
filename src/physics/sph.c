/* The "sph" physics module: options, the order of the SPH passes in a step,
 * time-step limits and the echo of resolved parameters.
 *   per step: [summation density] -> EOS -> wall values -> [correction tensors]
 *             -> momentum (+ continuity) */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/io.h"
#include "dmhs/body_force.h"
#include "sph_force.h"

const char *const sph_kernel_names[] = {"lucy",        "cubic", "wendland", "sph_kernel_kind",
                                        "SPH_KERNEL_", NULL};
const char *const sph_eos_names[] = {"tait",         "linear",   "linear_shifted",
                                     "sph_eos_kind", "SPH_EOS_", NULL};
const char *const sph_density_names[] = {"continuity", "summation", "sph_density_kind",
                                         "SPH_DENSITY_", NULL};
const char *const sph_wall_names[] = {"adami", "quadratic", "sph_wall_kind", "SPH_WALL_", NULL};
const char *const sph_sweep_names[] = {"auto",           "pairs",      "cells",
                                       "sph_sweep_kind", "SPH_SWEEP_", NULL};

typedef struct {
  sph_params params;  /* the scene's defaults, then the options (sph_defaults, sph_params_get) */
  module *body;       /* the body force module, NULL without one: the walls' hydrostatic part */
  PetscBool no_walls; /* sph_set_no_walls: no v_visc field */
  sph_wall_work *wall;
  sph_force_work force;
  sph_correction_work correction;
  sph_tensile_work tensile;
  PetscBool has_walls; /* any wall particle on any rank: else the wall pass is skipped */
} sph_data;

sph_params *sph_defaults(module *sph) {
  return sph && !strcmp(sph->name, "sph") ? &((sph_data *)sph->data)->params : NULL;
}

PetscErrorCode sph_set_liquid(module *m, double h, double rho0, double c0, double nu) {
  sph_params *sp = sph_defaults(m);
  PetscFunctionBeginUser;
  PetscCheck(sp, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "sph_set_liquid: module %s is not sph",
             m ? m->name : "(none)");
  sp->kernel = SPH_KERNEL_LUCY;
  sp->h = h;
  sp->rho0 = rho0;
  sp->c0 = c0;
  sp->nu = nu;
  sp->eos = SPH_EOS_TAIT;
  sp->density = SPH_DENSITY_CONTINUITY;
  PetscFunctionReturn(0);
}

PetscErrorCode sph_set_no_walls(module *m) {
  PetscFunctionBeginUser;
  PetscCheck(sph_defaults(m), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "sph_set_no_walls: module %s is not sph", m ? m->name : "(none)");
  ((sph_data *)m->data)->no_walls = PETSC_TRUE;
  PetscFunctionReturn(0);
}

const sph_params *sph_params_get(const sim *s) {
  return sph_defaults(sim_find_module(s, "sph"));
}

static PetscErrorCode sph_set_from_options(module *self, sim *s) {
  sph_params *sp = &((sph_data *)self->data)->params;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "SPH liquid (module sph)", NULL);
  PetscCall(options_read_enum("-sph_kernel", "Kernel: lucy, cubic (B-spline), wendland (C2)", NULL,
                              sph_kernel_names, (PetscEnum)sp->kernel, (PetscEnum *)&sp->kernel,
                              NULL));
  PetscCall(options_read_real("-sph_h", "Kernel support radius h [m] (W = 0 for r >= h)", NULL,
                              sp->h, &sp->h, NULL));
  PetscCall(options_read_real("-sph_rho0", "Reference density [kg/m^3]", NULL, sp->rho0, &sp->rho0,
                              NULL));
  PetscCall(
      options_read_real("-sph_c0", "Reference sound speed [m/s]", NULL, sp->c0, &sp->c0, NULL));
  PetscCall(
      options_read_real("-sph_nu", "Kinematic viscosity [m^2/s]", NULL, sp->nu, &sp->nu, NULL));
  PetscCall(options_read_enum(
      "-sph_eos", "Equation of state: tait, linear (c^2 rho), linear_shifted (c^2 (rho - rho0))",
      NULL, sph_eos_names, (PetscEnum)sp->eos, (PetscEnum *)&sp->eos, NULL));
  PetscCall(options_read_enum("-sph_density", "Density: continuity (d rho/dt) or summation", NULL,
                              sph_density_names, (PetscEnum)sp->density, (PetscEnum *)&sp->density,
                              NULL));
  PetscCall(options_read_real("-sph_av_alpha", "Monaghan artificial viscosity alpha [1] (0 = off)",
                              NULL, sp->av_alpha, &sp->av_alpha, NULL));
  PetscCall(options_read_real("-sph_av_beta", "Monaghan artificial viscosity beta [1]", NULL,
                              sp->av_beta, &sp->av_beta, NULL));
  PetscCall(options_read_real("-sph_p_background",
                              "Background pressure p_b [Pa] added to the EOS, p = EOS(rho) + p_b "
                              "(suppresses tensile voids)",
                              NULL, sp->p_background, &sp->p_background, NULL));
  PetscCall(options_read_real(
      "-sph_delta",
      "Density diffusion delta [1] of the continuity equation (delta-SPH, Molteni & "
      "Colagrossi 2009; 0 = off, 0.1 usual)",
      NULL, sp->delta, &sp->delta, NULL));
  PetscCall(options_read_real(
      "-sph_tensile_eps",
      "Artificial pressure against the tensile instability [1] (Monaghan 2000): where p < 0 a "
      "pair repulsion eps |p|/rho^2 (W(r)/W(dx))^4 keeps particles under tension from pairing "
      "up (0 = off, 0.2 usual)",
      NULL, sp->tensile_eps, &sp->tensile_eps, NULL));
  PetscCall(options_read_bool(
      "-sph_kernel_correction",
      "Corrected operators [1]: pressure gradient sum_j V_j (p_j - p_i) L_i grad W (exact for "
      "linear "
      "p, blind to a uniform p and to -sph_p_background), continuity with the corrected "
      "divergence, "
      "viscous term nu lap v exact for quadratic v, on any particle arrangement with a full "
      "support; not momentum-conserving (default true in the channel scenes, else false)",
      NULL, sp->kernel_correction, &sp->kernel_correction, NULL));
  PetscCall(options_read_enum(
      "-sph_wall_extrapolation",
      "Wall velocity of the viscous term [1]: adami (Shepard mirror, any wall shape) or quadratic "
      "(no-slip quadratic along the wall normal, exact for quadratic profiles; needs the wall "
      "geometry from the scene: default in the channel scenes, else adami)",
      NULL, sph_wall_names, (PetscEnum)sp->wall, (PetscEnum *)&sp->wall, NULL));
  PetscCall(options_read_enum(
      "-sph_force_sweep",
      "Momentum sweep [1]: auto (the vectorised sweep over cell ranges where it applies: an "
      "AVX-512 or AVX2 build, no kernel correction, Lucy or Wendland; else the pair list), pairs, "
      "or "
      "cells; both give the same bits",
      NULL, sph_sweep_names, (PetscEnum)sp->sweep, (PetscEnum *)&sp->sweep, NULL));
  PetscCall(options_read_bool(
      "-sph_density_predict",
      "Continuity: the forces see the density predicted for the end of the step, rho + dt "
      "drho, corrected to the trapezoid after them, instead of the half-step rho + dt/2 drho, "
      "which amplifies pressure oscillations at a rate omega^2 dt/4 (doc/theory.md; default "
      "true in the intestine and the vein, else false)",
      NULL, sp->density_predict, &sp->density_predict, NULL));
  PetscOptionsEnd();
  PetscCheck(sp->delta >= 0 && sp->delta <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sph_delta must lie in [0, 1] (got %g)", sp->delta);
  PetscCheck(sp->tensile_eps >= 0 && sp->tensile_eps <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sph_tensile_eps must lie in [0, 1] (got %.3g)", sp->tensile_eps);
  PetscCheck(
      sp->tensile_eps == 0 || s->dx > 0, s->comm, PETSC_ERR_ARG_INCOMP,
      "-sph_tensile_eps %.3g needs the scene's particle spacing, which scene %s does not set",
      sp->tensile_eps, s->scene_name);
  /* its reference W(dx) must be inside the support */
  PetscCheck(sp->tensile_eps == 0 || s->dx < sp->h, s->comm, PETSC_ERR_ARG_INCOMP,
             "-sph_tensile_eps %.3g: the particle spacing dx = %.3g m is not inside the support "
             "-sph_h %.3g m",
             sp->tensile_eps, s->dx, sp->h);
  PetscCheck(sp->delta == 0 || sp->density == SPH_DENSITY_CONTINUITY, s->comm, PETSC_ERR_ARG_INCOMP,
             "-sph_delta %g: density diffusion needs -sph_density continuity", sp->delta);
  PetscCheck(!sp->density_predict || sp->density == SPH_DENSITY_CONTINUITY, s->comm,
             PETSC_ERR_ARG_INCOMP, "-sph_density_predict needs -sph_density continuity");
  PetscCall(fields_enable("drho")); /* the continuity rates, zero with summation */
  PetscCall(fields_enable("p"));
  if (sp->density_predict)
    PetscCall(fields_enable("drho_prev"));
  if (!((sph_data *)self->data)->no_walls) /* the walls' velocity for the viscous term */
    PetscCall(fields_enable("v_visc"));
  PetscCheck(sp->h > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-sph_h must be > 0 (got %g)", sp->h);
  PetscCheck(sp->rho0 > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-sph_rho0 must be > 0 (got %g)",
             sp->rho0);
  PetscCheck(sp->c0 > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-sph_c0 must be > 0 (got %g)", sp->c0);
  PetscCheck(sp->nu >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-sph_nu must be >= 0 (got %g)",
             sp->nu);
  PetscCheck(sp->av_alpha >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sph_av_alpha must be >= 0 (got %g)", sp->av_alpha);
  PetscCheck(sp->av_beta >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sph_av_beta must be >= 0 (got %g)", sp->av_beta);
  PetscCheck(sp->p_background >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-sph_p_background must be >= 0 (got %g Pa)", sp->p_background);
  self->reach = sp->h;
  /* the integrator advances rho with the rates this module adds (continuity) */
  if (sp->density == SPH_DENSITY_CONTINUITY)
    self->needs |= MODULE_INTEGRATES_DENSITY;
  if (sp->density_predict)
    self->needs |= MODULE_PREDICTS_DENSITY;
  PetscFunctionReturn(0);
}

static PetscErrorCode sph_setup(module *self, sim *s) {
  sph_data *d = self->data;
  const sph_params *sp = &d->params;
  PetscInt n_local = particles_count_type(&s->ps, PTYPE_WALL), n_walls;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&n_local, &n_walls, 1, MPIU_INT, MPI_SUM, s->comm));
  d->has_walls = n_walls > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(!d->has_walls || !d->no_walls, s->comm, PETSC_ERR_PLIB,
             "scene %s said it builds no walls (sph_set_no_walls) but built %" PetscInt_FMT,
             s->scene_name, n_walls);
  d->body = sim_find_module(s, "body_force");
  PetscCheck(sp->wall != SPH_WALL_QUADRATIC || !d->has_walls || fields_enabled("to_surface"),
             s->comm, PETSC_ERR_ARG_INCOMP,
             "-sph_wall_extrapolation quadratic needs each wall particle's vector to the wall "
             "surface, which scene %s does not provide (the channel scenes do): use "
             "-sph_wall_extrapolation adami",
             s->scene_name);
  PetscCall(sph_wall_create(&d->wall));
  /* in every snapshot: what interpolating the fields needs (scripts/post/sph_grid.py) */
  PetscCall(io_snapshot_attribute_string(s, "sph_kernel", sph_kernel_names[sp->kernel]));
  PetscCall(io_snapshot_attribute_real(s, "sph_h", sp->h));
  /* the vectorised sweep walks the cells; walls, summation density, the correction and the
   * stress diagnostics and the artificial pressure read the pair list */
  if (sph_force_cells_applies(sp) && !d->has_walls && sp->tensile_eps == 0 &&
      sp->density == SPH_DENSITY_CONTINUITY && !fields_enabled("stress_xx"))
    self->needs |= MODULE_CELLS_ONLY;
  /* the cells sweep writes every owned row's a and drho back: when it comes first in an
   * evaluation it starts its sums from zero itself (nothing else in sph_compute adds to
   * them before it: the EOS and the wall pass write rho, p and v_visc) */
  if (sph_force_cells_applies(sp) && sp->density == SPH_DENSITY_CONTINUITY)
    self->needs |= MODULE_SETS_RATES;
  PetscFunctionReturn(0);
}

static PetscErrorCode sph_compute(module *self, sim *s) {
  sph_data *d = self->data;
  const sph_params *sp = &d->params;
  PetscFunctionBeginUser;
  if (sp->density == SPH_DENSITY_SUMMATION)
    PetscCall(sph_density_summation(s, sp));
  PetscCall(sph_eos_compute(s, sp));
  if (d->has_walls) {
    /* the body force's value at this evaluation's time: its module's prepare phase ran
     * before any compute (sim_add_module_forces) */
    double g[DMHS_DIM] = {0.0, 0.0};
    if (d->body)
      body_force_current(d->body, g);
    PetscCall(sph_wall_compute(s, sp, g, d->wall));
  }
  /* without walls every sweep's viscous term reads v_est (no copy into v_visc) */
  d->force.visc_is_est = d->has_walls ? PETSC_FALSE : PETSC_TRUE;
  if (sp->kernel_correction)
    PetscCall(sph_correction_compute(s, sp, sph_viscous_velocity(&s->ps, d->force.visc_is_est),
                                     &d->correction));
  if (sp->kernel_correction)
    PetscCall(sph_force_compute(s, sp, &d->force, d->correction.corr,
                                (const double(*)[2])d->correction.pair));
  else
    PetscCall(sph_force_compute(s, sp, &d->force, NULL, NULL));
  if (sp->tensile_eps > 0)
    PetscCall(sph_tensile_compute(s, sp, &d->tensile));
  PetscFunctionReturn(0);
}

/* Lattice points (other than the origin) strictly inside the support at spacing dx. */
static int neighbours_at_rest(double h, double dx) {
  const int reach = (int)ceil(h / dx);
  int n = 0;
  for (int a = -reach; a <= reach; a++)
    for (int b = -reach; b <= reach; b++)
      if ((a || b) && sqrt((double)(a * a + b * b)) * dx < h)
        n++;
  return n;
}

/* Pre-flight: enough neighbours inside the support at the scene's rest spacing. */
static PetscErrorCode sph_preflight(module *self, sim *s, int *problems) {
  const sph_params *sp = &((sph_data *)self->data)->params;
  PetscFunctionBeginUser;
  if (s->dx <= 0)
    PetscFunctionReturn(0);
  const int nb = neighbours_at_rest(sp->h, s->dx);
  const PetscBool few = nb < 12 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscPrintf(s->comm,
                        "  %-18s h/dx = %.3g: %d neighbours inside the support at rest spacing%s\n",
                        "sph support", sp->h / s->dx, nb,
                        few ? "  TOO FEW (need >= 12 in 2D; h <= dx leaves none)" : ""));
  *problems += few;
  PetscFunctionReturn(0);
}

/* The classic limits were derived for a smoothing length h_s with support 2 h_s;
 * our h is the support, so they are evaluated with h_s = h/2. */
static PetscErrorCode sph_max_dt(module *self, sim *s, dt_limits *l) {
  const sph_params *sp = &((sph_data *)self->data)->params;
  const double hs = 0.5 * sp->h;
  double local[2], global[2]; /* max|v|^2 (all), max|a|^2 (liquid) */
  PetscFunctionBeginUser;
  /* evaluated before every step: squares, one root each after the reduction. The maxima
   * are taken over the squares' bits as unsigned integers, which order as the values do for
   * numbers >= 0, and the liquid's by a mask, so that the loop vectorises (no NaN gets here:
   * the state check stops the run first) */
  uint64_t max_v2 = 0, max_a2 = 0;
  const double *restrict v = &s->ps.v[0][0], *restrict a = &s->ps.a[0][0];
  const PetscInt *restrict type = s->ps.type;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    const double v2 = v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1];
    const double a2 = a[2 * i] * a[2 * i] + a[2 * i + 1] * a[2 * i + 1];
    uint64_t bits_v2, bits_a2;
    memcpy(&bits_v2, &v2, sizeof(bits_v2));
    memcpy(&bits_a2, &a2, sizeof(bits_a2));
    bits_a2 &= (uint64_t)0 - (uint64_t)(type[i] == PTYPE_FLUID);
    max_v2 = bits_v2 > max_v2 ? bits_v2 : max_v2;
    max_a2 = bits_a2 > max_a2 ? bits_a2 : max_a2;
  }
  memcpy(&local[0], &max_v2, sizeof(local[0]));
  memcpy(&local[1], &max_a2, sizeof(local[1]));
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, s->comm));
  global[0] = PetscSqrtReal(global[0]);
  global[1] = PetscSqrtReal(global[1]);
  const double vmax_global = global[0];
  /* Monaghan's artificial viscosity widens the signal speed by 1.2 (alpha c0 + beta max|v|) */
  const double signal =
      sp->c0 + vmax_global + 1.2 * (sp->av_alpha * sp->c0 + sp->av_beta * vmax_global);
  PetscCall(dt_limits_add(l, "sph sound speed", "0.25 h_s/(c0 + max|v| [+ AV]), h_s = h/2",
                          0.25 * hs / signal));
  if (sp->nu > 0)
    PetscCall(
        dt_limits_add(l, "sph viscosity", "0.125 h_s^2/nu, h_s = h/2", 0.125 * hs * hs / sp->nu));
  /* Monaghan's force criterion on the accelerations of the last force
   * evaluation (none before the first one) */
  /* the same criterion on the body force's peak (it may drive an empty or resting liquid) */
  const module *body = sim_find_module(s, "body_force");
  const double a_body = body ? body_force_peak(body) : 0.0;
  if (a_body > 0)
    PetscCall(dt_limits_add(l, "body force", "0.25 sqrt(h_s/|a|), h_s = h/2",
                            0.25 * PetscSqrtReal(hs / a_body)));
  if (global[1] > 0)
    PetscCall(dt_limits_add(l, "sph acceleration", "0.25 sqrt(h_s/max|a|), liquid, h_s = h/2",
                            0.25 * PetscSqrtReal(hs / global[1])));
  PetscFunctionReturn(0);
}

static PetscErrorCode sph_view(module *self, sim *s, PetscViewer v) {
  const sph_params *sp = &((sph_data *)self->data)->params;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(
      v, "sph: kernel %s, h = %g m (h/dx = %g), rho0 = %g kg/m^3, c0 = %g m/s, nu = %g m^2/s\n",
      sph_kernel_names[sp->kernel], sp->h, sp->h / s->dx, sp->rho0, sp->c0, sp->nu));
  PetscCall(PetscViewerASCIIPrintf(v,
                                   "sph: eos %s, background pressure %g Pa, density %s, artificial "
                                   "viscosity alpha = %g beta = %g, walls: %s extrapolation\n",
                                   sph_eos_names[sp->eos], sp->p_background,
                                   sph_density_names[sp->density], sp->av_alpha, sp->av_beta,
                                   sph_wall_names[sp->wall]));
  if (sp->delta > 0)
    PetscCall(
        PetscViewerASCIIPrintf(v, "sph: density diffusion delta = %g (delta-SPH)\n", sp->delta));
  if (sp->tensile_eps > 0)
    PetscCall(PetscViewerASCIIPrintf(
        v, "sph: artificial pressure eps = %g where p < 0 (Monaghan 2000, (W(r)/W(dx))^4)\n",
        sp->tensile_eps));
  if (sp->density_predict)
    PetscCall(PetscViewerASCIIPrintf(v, "sph: forces see the density predicted for the end of "
                                        "the step (-sph_density_predict)\n"));
  if (sp->kernel_correction)
    PetscCall(PetscViewerASCIIPrintf(v,
                                     "sph: kernel correction: pressure gradient exact for linear p "
                                     "(difference form), continuity with the corrected divergence, "
                                     "viscous term exact for quadratic v\n"));
  PetscFunctionReturn(0);
}

static PetscErrorCode sph_virial(module *self, sim *s, double (*W)[3]) {
  PetscFunctionBeginUser;
  const sph_data *d = self->data;
  PetscCall(
      sph_stress_virial(s, &d->params, sph_viscous_velocity(&s->ps, d->force.visc_is_est), W));
  PetscFunctionReturn(0);
}

static PetscErrorCode sph_destroy(module *self) {
  sph_data *d = self->data;
  PetscFunctionBeginUser;
  PetscCall(sph_wall_destroy(&d->wall));
  PetscCall(PetscFree3(d->force.P, d->force.inv_rho, d->force.J));
  if (d->force.cells)
    PetscCall(sph_cells_work_destroy(d->force.cells));
  PetscCall(PetscFree(d->force.cells));
  PetscCall(sph_correction_destroy(&d->correction));
  PetscCall(sph_tensile_destroy(&d->tensile));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode sph_module_create(module **m) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(m));
  (*m)->name = "sph";
  (*m)->needs = MODULE_NEEDS_PAIRS;
  /* x for the pairs, v of the walls (correction's divergence, Adami's mirror), v_est for the
   * viscous and continuity terms, rho for the EOS and 1/rho (p and v_visc are recomputed on
   * ghosts: the EOS on every row, the wall pass forwards its own) */
  static const char *const reads[] = {"x", "v", "v_est", "rho", NULL};
  (*m)->ghost_reads = reads;
  (*m)->set_from_options = sph_set_from_options;
  (*m)->setup = sph_setup;
  (*m)->compute = sph_compute;
  (*m)->max_dt = sph_max_dt;
  (*m)->view = sph_view;
  (*m)->destroy = sph_destroy;
  (*m)->virial = sph_virial;
  (*m)->preflight = sph_preflight;
  PetscCall(PetscNew((sph_data **)&(*m)->data));
  PetscFunctionReturn(0);
}
