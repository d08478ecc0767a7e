/* Time-step control: the limits re-evaluated before every step, the fixed-dt
 * check, the automatic dt with its band, growth bound and floor, dt.csv and
 * the step's time (see timestep.h). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/dt_limits.h"
#include "dmhs/io.h"
#include "dmhs/timestep.h"
#include "dmhs/substep.h"
#include "dmhs/solid_modes.h"
#include "dmhs/csv.h"
#include "dmhs/events.h"
#include "dmhs/fields.h"

typedef enum { SUBSTEP_RESPA, SUBSTEP_HELD } substep_scheme;
static const char *const substep_scheme_names[] = {"respa", "held", "substep_scheme", "SUBSTEP_",
                                                   NULL};

PetscErrorCode timestep_set_from_options(sim *s, timestep *ts) {
  PetscBool safety_set, growth_set, min_set;
  PetscFunctionBeginUser;
  ts->substeps_option = 1;
  s->substeps.n = 1;
  s->substeps.respa = PETSC_FALSE;
  s->substeps.mode_factor = SOLID_MODES_LIMIT;
  ts->safety = DT_SAFETY_DEFAULT;
  ts->growth = DT_GROWTH_DEFAULT;
  ts->dt_min = 0;
  PetscOptionsBegin(s->comm, NULL, "dmhs time stepping", NULL);
  PetscCall(options_read_real(
      "-dt",
      "Time step [s] (0 = automatic: follows -dt_safety x the smallest stability limit, "
      "re-evaluated every step)",
      NULL, s->dt, &s->dt, NULL));
  PetscCall(options_read_real("-dt_safety",
                              "With -dt 0: dt as a fraction of the smallest limit [1]", NULL,
                              ts->safety, &ts->safety, &safety_set));
  PetscCall(options_read_real("-dt_growth",
                              "With -dt 0: largest growth of dt from one step to the next [1]",
                              NULL, ts->growth, &ts->growth, &growth_set));
  PetscCall(options_read_real(
      "-dt_min",
      "With -dt 0: the run stops when dt would fall below this [s] (0 = 1e-3 x the first "
      "automatic dt)",
      NULL, ts->dt_min, &ts->dt_min, &min_set));
  PetscCall(options_read_int("-solid_substeps",
                             "Sub-steps of the solids' bonds and angles per step [1] (1 = off, 0 = "
                             "automatic from the ratio of the liquid's to the solids' limits)",
                             NULL, ts->substeps_option, &ts->substeps_option, NULL));
  substep_scheme scheme = s->substeps.respa ? SUBSTEP_RESPA : SUBSTEP_HELD;
  PetscCall(options_read_enum(
      "-solid_substeps_scheme",
      "With sub-steps: how the forces not sub-cycled (the liquid's, loads) act on the rows that "
      "move on them [1]: respa (half a step's worth at each end of the step, as the liquid's "
      "own kicks: time-reversible, r-RESPA) or held (their start-of-step value on every "
      "sub-step, as SPHinXsys)",
      NULL, substep_scheme_names, (PetscEnum)scheme, (PetscEnum *)&scheme, NULL));
  s->substeps.respa = scheme == SUBSTEP_RESPA ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(options_read_real(
      "-solid_mode_dt_factor",
      "With sub-steps: dt <= this / omega, omega the Gershgorin bound of the solids' fastest "
      "mode [1] (0 = no such limit; the default stays clear of the multiple-time-step "
      "resonances; with -bond_damping and -angle_damping 0.01, 2.5 was measured quiet: "
      "doc/stability.md)",
      NULL, s->substeps.mode_factor, &s->substeps.mode_factor, NULL));
  PetscOptionsEnd();
  PetscCheck(s->substeps.mode_factor >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-solid_mode_dt_factor must be >= 0 (got %g; 0 = no fastest-mode limit)",
             s->substeps.mode_factor);
  PetscCheck(ts->substeps_option >= 0 && ts->substeps_option <= SUBSTEPS_MAX, s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-solid_substeps must be in [0, %d] (got %" PetscInt_FMT "; 1 = off, 0 = automatic)",
             SUBSTEPS_MAX, ts->substeps_option);
  s->substeps.on = ts->substeps_option != 1 ? PETSC_TRUE : PETSC_FALSE;
  /* the held acceleration is a particle field: it must exist before the scene builds */
  if (s->substeps.on) {
    PetscCall(fields_enable("a_hold"));
    PetscCall(fields_enable("substepped"));
  }
  PetscCheck(s->dt >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-dt must be >= 0 (got %g; 0 = automatic)", s->dt);
  PetscCheck(ts->safety > 0 && ts->safety <= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-dt_safety must be in (0, 1] (got %g)", ts->safety);
  PetscCheck(ts->growth >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-dt_growth must be >= 1 (got %g)",
             ts->growth);
  PetscCheck(ts->dt_min >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-dt_min must be >= 0 s (got %g)",
             ts->dt_min);
  /* a scene may still pick its own default dt: which options belong to the
   * automatic dt is checked once dt is known (timestep_choose_first) */
  ts->automatic_options_set = (safety_set || growth_set || min_set) ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode timestep_collect_limits(sim *s, dt_limits *l) {
  PetscFunctionBeginUser;
  l->n = 0;
  for (int m = 0; m < s->n_modules; m++) {
    const int first = l->n;
    if (s->modules[m]->max_dt)
      PetscCall(s->modules[m]->max_dt(s->modules[m], s, l));
    for (int k = first; k < l->n; k++)
      l->item[k].inner = s->modules[m]->solid_internal;
  }
  const int first = l->n;
  PetscCall(solid_modes_add_limit(s, l));
  for (int k = first; k < l->n; k++)
    l->item[k].inner = PETSC_FALSE; /* it bounds dt itself */
  PetscFunctionReturn(0);
}

double timestep_dt_for(const sim *s, PetscBool inner) {
  return inner && s->substeps.on ? s->dt / (double)s->substeps.n : s->dt;
}

/* The smallest limit on dt itself: the others', and (sub-cycling with a fixed
 * N) N x the solids'. With -solid_substeps 0 the solids' limits do not bound
 * dt (N follows them) unless nothing else does. */
static double timestep_effective_limit(const timestep *ts, const dt_limits *l, int *which) {
  double best = INFINITY, inner_best = INFINITY;
  int inner_which = -1;
  *which = -1;
  for (int k = 0; k < l->n; k++) {
    const double v = l->item[k].value;
    if (ts->substeps_option != 1 && l->item[k].inner) {
      if (v < inner_best) {
        inner_best = v;
        inner_which = k;
      }
      if (ts->substeps_option > 0 && v * (double)ts->substeps_option < best) {
        best = v * (double)ts->substeps_option;
        *which = k;
      }
    } else if (v < best) {
      best = v;
      *which = k;
    }
  }
  if (*which < 0 && inner_which >= 0) { /* only the solids' limits: nothing to gain */
    *which = inner_which;
    best = inner_best;
  }
  return best;
}

/* Sub-steps for the current dt: fixed, or the fewest that keep dt/N within
 * the safety fraction of the solids' smallest limit. */
static PetscErrorCode timestep_choose_substeps(sim *s, timestep *ts, const dt_limits *l) {
  double inner = INFINITY;
  int which = -1;
  PetscFunctionBeginUser;
  if (!s->substeps.on)
    PetscFunctionReturn(0);
  if (ts->substeps_option > 0) {
    s->substeps.n = ts->substeps_option;
    PetscFunctionReturn(0);
  }
  for (int k = 0; k < l->n; k++)
    if (l->item[k].inner && l->item[k].value < inner) {
      inner = l->item[k].value;
      which = k;
    }
  if (which < 0) {
    s->substeps.n = 1;
    PetscFunctionReturn(0);
  }
  const double n = ceil(s->dt / (ts->safety * inner) * (1.0 - 1e-12));
  PetscCheck(n <= SUBSTEPS_MAX, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "step %" PetscInt_FMT
             ": -solid_substeps 0 would need %g sub-steps of dt = %g s for the "
             "%s limit %g s (at most %d): lower -dt",
             s->step, n, s->dt, l->item[which].name, inner, SUBSTEPS_MAX);
  s->substeps.n = n < 1 ? 1 : (PetscInt)n;
  PetscFunctionReturn(0);
}

static void timestep_note_binding(timestep *ts, const dt_limits *l) {
  int which;
  ts->binding_value = timestep_effective_limit(ts, l, &which);
  if (which >= 0)
    PetscStrncpy(ts->binding, l->item[which].name, sizeof(ts->binding));
}

PetscErrorCode timestep_choose_first(sim *s, timestep *ts, const dt_limits *l) {
  int which;
  PetscFunctionBeginUser;
  ts->adaptive = s->dt <= 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCheck(ts->adaptive || !ts->automatic_options_set, s->comm, PETSC_ERR_ARG_INCOMP,
             "-dt_safety, -dt_growth and -dt_min apply to the automatic time step only; with -dt "
             "%g (fixed) drop them or give -dt 0",
             s->dt);
  s->t_anchor = 0;
  s->step_anchor = 0;
  timestep_note_binding(ts, l);
  if (!ts->adaptive) {
    PetscCall(timestep_choose_substeps(s, ts, l));
    PetscFunctionReturn(0);
  }
  const double limit = timestep_effective_limit(ts, l, &which);
  PetscCheck(which >= 0, s->comm, PETSC_ERR_ARG_WRONG,
             "-dt 0 (automatic) needs at least one time-step limit, and no module gives one");
  s->dt = ts->safety * limit;
  PetscCall(timestep_choose_substeps(s, ts, l));
  if (ts->dt_min <= 0)
    ts->dt_min = DT_MIN_FRACTION * s->dt;
  PetscCheck(s->dt >= ts->dt_min, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "the first automatic dt %g s (%g x the %s limit %g s) is below -dt_min %g s: the "
             "state at t = 0 is too stiff for the floor; lower -dt_min or soften the setup",
             s->dt, ts->safety, l->item[which].name, limit, ts->dt_min);
  PetscCall(PetscPrintf(s->comm,
                        "dt = %g s chosen automatically (-dt 0): %g x the smallest limit, %s; "
                        "re-evaluated every step (floor -dt_min %g s)\n",
                        s->dt, ts->safety, l->item[which].name, ts->dt_min));
  PetscFunctionReturn(0);
}

static PetscErrorCode timestep_csv_row(sim *s, timestep *ts) {
  PetscFunctionBeginUser;
  if (!ts->csv)
    PetscFunctionReturn(0);
  if (s->substeps.on)
    PetscCall(csv_row(ts->csv, "dt.csv", "%" PetscInt_FMT ",%.17g,%.17g,%s,%" PetscInt_FMT "\n",
                      s->step, s->t, s->dt, ts->binding, s->substeps.n));
  else
    PetscCall(csv_row(ts->csv, "dt.csv", "%" PetscInt_FMT ",%.17g,%.17g,%s\n", s->step, s->t, s->dt,
                      ts->binding));
  PetscFunctionReturn(0);
}

/* dt.csv: the first evaluation of a run opens it; a fresh run records its
 * first dt, a restarted one keeps the rows before its step (it writes the row
 * of its own step again, if dt changes there). */
static PetscErrorCode timestep_open_csv(sim *s, timestep *ts) {
  PetscFunctionBeginUser;
  const char *header = s->substeps.on ? "step,t,dt,limit,substeps\n" : "step,t,dt,limit\n";
  PetscCall(csv_open_keeping(s, "dt.csv", header, (double)s->step - 0.5, &ts->csv));
  if (!s->io->restarted)
    PetscCall(timestep_csv_row(s, ts));
  PetscFunctionReturn(0);
}

/* Fixed dt: every limit the state now sets must still hold (the solids' own
 * against dt/N when sub-cycling). */
static PetscErrorCode timestep_check_fixed(sim *s, timestep *ts, const dt_limits *l) {
  PetscFunctionBeginUser;
  for (int k = 0; k < l->n; k++) {
    const dt_limit *it = &l->item[k];
    const double dt = timestep_dt_for(s, it->inner);
    if (dt <= it->value * (1.0 + 1e-12))
      continue;
    const char *what = dt < s->dt ? "dt/substeps" : "dt";
    PetscCheck(ts->on_exceeded == PREFLIGHT_WARN, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "step %" PetscInt_FMT
               ", t = %g s: %s = %g s exceeds the %s limit %g s (%s) that the "
               "state now sets; lower -dt, use -dt 0 (automatic), or -preflight warn to run on",
               s->step, s->t, what, dt, it->name, it->value, it->formula);
    if (!ts->warned)
      PetscCall(PetscPrintf(s->comm,
                            "WARNING: step %" PetscInt_FMT ", t = %g s: %s = %g s exceeds the %s "
                            "limit %g s (%s); continuing (-preflight warn), printed once\n",
                            s->step, s->t, what, dt, it->name, it->value, it->formula));
    ts->warned = PETSC_TRUE;
    break;
  }
  PetscFunctionReturn(0);
}

/* Automatic dt: the band, the growth bound and the floor; then the sub-steps. */
static PetscErrorCode timestep_adapt(sim *s, timestep *ts, const dt_limits *l) {
  int which;
  PetscFunctionBeginUser;
  const double limit = timestep_effective_limit(ts, l, &which);
  PetscCheck(which >= 0, s->comm, PETSC_ERR_PLIB, "no time-step limit at step %" PetscInt_FMT,
             s->step);
  const double target = ts->safety * limit;
  double dt = s->dt;
  if (dt > target)
    dt = DT_BAND_MID * target;
  else if (dt < DT_BAND_LOW * target)
    dt = PetscMin(ts->growth * dt, DT_BAND_MID * target);
  PetscCheck(dt >= ts->dt_min, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "step %" PetscInt_FMT ", t = %g s: the automatic dt would fall to %g s, below -dt_min "
             "%g s, driven by the %s limit %g s (%s); the run is stopped here (its last checkpoint "
             "and outputs stay valid)",
             s->step, s->t, dt, ts->dt_min, l->item[which].name, limit, l->item[which].formula);
  const PetscInt n_sub_before = s->substeps.n;
  const PetscBool dt_changed = dt != s->dt ? PETSC_TRUE : PETSC_FALSE;
  s->dt = dt;
  PetscCall(timestep_choose_substeps(s, ts, l));
  if (!dt_changed && s->substeps.n == n_sub_before)
    PetscFunctionReturn(0);
  if (dt_changed) {
    s->t_anchor = s->t;
    s->step_anchor = s->step;
  }
  ts->n_changes++;
  PetscCall(timestep_csv_row(s, ts));
  PetscFunctionReturn(0);
}

PetscErrorCode timestep_before_step(sim *s, timestep *ts) {
  dt_limits limits;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.timestep, 0, 0, 0, 0));
  if ((ts->adaptive || ts->substeps_option == 0) && !ts->csv && !s->rank)
    PetscCall(timestep_open_csv(s, ts));
  PetscCall(timestep_collect_limits(s, &limits));
  timestep_note_binding(ts, &limits);
  if (ts->adaptive)
    PetscCall(timestep_adapt(s, ts, &limits));
  else {
    const PetscInt n_sub_before = s->substeps.n;
    PetscCall(timestep_choose_substeps(s, ts, &limits));
    if (s->substeps.n != n_sub_before)
      PetscCall(timestep_csv_row(s, ts));
    PetscCall(timestep_check_fixed(s, ts, &limits));
  }
  PetscCall(PetscLogEventEnd(events.timestep, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

void timestep_advance(sim *s) {
  s->step++;
  /* from the anchor: no round-off accumulates over the steps of one dt */
  s->t = s->t_anchor + (double)(s->step - s->step_anchor) * s->dt;
}

PetscErrorCode timestep_finish(timestep *ts) {
  PetscFunctionBeginUser;
  PetscCall(csv_close(&ts->csv, "dt.csv"));
  PetscFunctionReturn(0);
}

PetscErrorCode timestep_stability_report(sim *s, timestep *ts) {
  dt_limits limits = {0};
  int problems = 0;
  PetscFunctionBeginUser;
  PetscCall(timestep_collect_limits(s, &limits));
  PetscCall(timestep_choose_first(s, ts, &limits)); /* -dt 0: the first dt */
  if (s->substeps.on)
    PetscCall(PetscPrintf(
        s->comm,
        "Stability report (pre-flight), dt = %g s, %" PetscInt_FMT
        " solid sub-steps (the solids' own limits, marked *, against dt/%" PetscInt_FMT "):\n",
        s->dt, s->substeps.n, s->substeps.n));
  else
    PetscCall(PetscPrintf(s->comm, "Stability report (pre-flight), dt = %g s:\n", s->dt));
  for (int k = 0; k < limits.n; k++) {
    const dt_limit *l = &limits.item[k];
    const double dt = timestep_dt_for(s, l->inner);
    const PetscBool over = dt > l->value * (1.0 + 1e-12) ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(PetscPrintf(s->comm, "  %-18s %-48s %11.4e s  dt/limit = %6.3f%s%s\n", l->name,
                          l->formula, l->value, dt / l->value,
                          s->substeps.on && l->inner ? " *" : "", over ? "  EXCEEDED" : ""));
    problems += over;
  }
  for (int m = 0; m < s->n_modules; m++) /* the modules' own checks (e.g. SPH's support) */
    if (s->modules[m]->preflight)
      PetscCall(s->modules[m]->preflight(s->modules[m], s, &problems));
  if (problems) {
    const char *what =
        "dt exceeds a time-step limit or the kernel support holds too few neighbours "
        "(see the report above): lower -dt (or -dt 0 for automatic) / raise -sph_h";
    PetscCheck(ts->on_exceeded == PREFLIGHT_WARN, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "pre-flight check failed: %s; -preflight warn runs anyway", what);
    PetscCall(PetscPrintf(s->comm, "WARNING: pre-flight check: %s (continuing: -preflight warn)\n",
                          what));
  }
  PetscFunctionReturn(0);
}
