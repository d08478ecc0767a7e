/* Time-step control. Before every step the time-step limits of every enabled
 * module are evaluated again from the current state (sound speed with the
 * current max|v|, the largest fluid acceleration, the nonlinear bond at its
 * largest stretch, repulsion at the closest approach, angles at their
 * shortest arm, ...).
 *   fixed dt (-dt > 0): the run stops, naming the limit, as soon as dt
 *     exceeds one (-preflight warn: a warning, once, and it runs on);
 *   automatic (-dt 0): dt follows -dt_safety x the smallest limit. It is kept
 *     while it lies in [DT_BAND_LOW, 1] x that target (so a slowly moving
 *     limit does not change dt every step), cut to DT_BAND_MID x the target
 *     when it rises above it, and grown by at most -dt_growth per step when it
 *     falls below the band. A target under -dt_min stops the run, naming the
 *     limit that drove it there. Every change is a row of
 *     <output_dir>/dt.csv (step,t,dt,limit).
 * Solid sub-cycling (-solid_substeps N, src/core/substep.c): the limits of
 * the solid_internal modules (bonds, angles) bound dt/N, the others dt; N = 0
 * picks N every step as the smallest that keeps dt/N within -dt_safety (0.8
 * by default) x the solids' limit. dt.csv gains a column substeps. dt itself
 * stays below 1.25/omega, omega a bound on the solids' fastest mode
 * (solid_modes.h): near it the liquid's once-a-step forces make them resonate.
 * t advances as t_anchor + (step - step_anchor) dt with the anchor moved at
 * each change: a fixed-dt run keeps t = step dt exactly, and the anchor is
 * checkpointed, so a restart continues the same t bit for bit. */
#ifndef DMHS_TIMESTEP_H
#define DMHS_TIMESTEP_H
#include <stdio.h>
#include <petscsys.h>

struct sim;
struct dt_limits;

#define DT_SAFETY_DEFAULT 0.8
#define DT_GROWTH_DEFAULT 1.05
#define DT_BAND_LOW       0.9
#define DT_BAND_MID       0.95
/* -dt_min 0: this fraction of the first automatic dt */
#define DT_MIN_FRACTION 1e-3

typedef enum { PREFLIGHT_ERROR, PREFLIGHT_WARN } preflight_action;
extern const char *const preflight_action_names[];

typedef struct timestep {
  preflight_action on_exceeded;    /* -preflight: a limit exceeded stops the run or warns */
  PetscBool adaptive;              /* -dt 0 (set by timestep_choose_first) */
  PetscBool automatic_options_set; /* -dt_safety, -dt_growth or -dt_min was given */
  double safety;                   /* -dt_safety [1] */
  double growth;                   /* -dt_growth [1]: largest dt_new/dt_old of one step */
  double dt_min;                   /* -dt_min [s] (0 until the first automatic dt sets it) */
  char binding[32];                /* the smallest limit at the last evaluation */
  double binding_value;
  PetscInt n_changes;       /* dt changes during this run (restart: since it) */
  PetscBool warned;         /* fixed dt over a limit with -preflight warn: said once */
  FILE *csv;                /* rank 0: dt.csv */
  PetscInt substeps_option; /* -solid_substeps: 1 = off, 0 = automatic */
} timestep;

/* -dt, -dt_safety, -dt_growth, -dt_min, -solid_substeps. */
PetscErrorCode timestep_set_from_options(struct sim *s, timestep *ts);
/* Every enabled module's limits for the current state. */
PetscErrorCode timestep_collect_limits(struct sim *s, struct dt_limits *l);
/* Pre-flight, with -dt 0: the first dt from the limits at t = 0 (and the
 * default floor). */
PetscErrorCode timestep_choose_first(struct sim *s, timestep *ts, const struct dt_limits *l);
/* Before each step: the limits from the current state; checks (fixed dt) or
 * adapts (automatic) dt. */
PetscErrorCode timestep_before_step(struct sim *s, timestep *ts);
/* After the drift: step + 1 and its time. */
void timestep_advance(struct sim *s);
/* The dt a limit is compared with: dt/N for the solids' own limits when
 * sub-cycling, dt otherwise. */
double timestep_dt_for(const struct sim *s, PetscBool inner);
/* Pre-flight: every module's limits against dt (and the modules' own checks); stops the run
 * on a problem unless -preflight warn. */
PetscErrorCode timestep_stability_report(struct sim *s, timestep *ts);
/* Closes dt.csv. */
PetscErrorCode timestep_finish(timestep *ts);

#endif
