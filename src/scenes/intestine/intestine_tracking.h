/* The diagnostic "intestine" (src/scenes/intestine/intestine_tracking.c): the tracked
 * liquid of the intestine scene.
 * <output_dir>/intestine.csv at every output time (and t = 0):
 *   t, sub (sub-period, -1 = no wave), x_F [m] (mean x of white),
 *   white_0 .. white_{N+1} (counts per pocket, N+1 = overflow), alpha
 *   (fraction of white out of pocket 0), [red_0 .. red_{N+1}], overflow
 *   (all parked fluid), fluid (fluid in the computation), rho_dev and mach
 *   (max |rho/rho0 - 1| and max |v|/c0 of the liquid), in_membrane and
 *   through (liquid particles lodged between the membrane's top and bottom
 *   layers, and below its bottom layer), lift_0 .. lift_N
 *   (mean y displacement of the middle third of each segment [m]),
 *   s_0 .. s_N (the schedule's value per pocket).
 * At the end, from the rows since the wave's start (intestine_measures.h): u_F
 * (the line over the run's whole waves, or the initial slope where it does not
 * fit), V_w, alpha after one period and at the last whole wave's end, u_P,
 * u_S, Re, Re_P, Ga, Fr, Lambda (doc/theory.md, "Peristalsis and tracking"),
 * in the report and <output_dir>/intestine-summary.csv (key,value,note: n/a
 * with its reason where a value is undefined). */
#ifndef DMHS_INTESTINE_TRACKING_H
#define DMHS_INTESTINE_TRACKING_H
#include "dmhs/sim.h"
#include "dmhs/membrane_leak.h"

/* tracer values of the tracked sets */
#define INTESTINE_TRACER_WHITE 1
#define INTESTINE_TRACER_RED   2

typedef struct intestine_layout {
  PetscInt n_pockets;             /* N + 1 */
  double b, dx, level, amplitude; /* pocket length, spacing, liquid level, haustral depth [m] */
  PetscBool red;                  /* a second set is tracked */
  PetscInt64 n_fluid;             /* fluid gids 0 .. n_fluid - 1 */
  membrane_layout mem;            /* the liquid must stay above its top layer */
  module *peri, *body;            /* the wave's schedule, gravity */
  double uf_r2_min;               /* u_F: the whole-run line fits when its R^2 >= this */
  PetscInt uf_initial_waves;      /* u_F's initial slope: over the first this many waves */
} intestine_layout;

PetscErrorCode intestine_tracking_register(sim *s, const intestine_layout *lay);

#endif
