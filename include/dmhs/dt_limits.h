/* Time-step limits: what every module's max_dt (module.h) reports for the current state,
 * a name, the formula it evaluated and its value. The driver's time-step control
 * (timestep.h) takes the smallest. */
#ifndef DMHS_DT_LIMITS_H
#define DMHS_DT_LIMITS_H
#include <petscsys.h>

#define DT_LIMITS_MAX 32
typedef struct dt_limit {
  char name[32];    /* e.g. "sph sound speed" */
  char formula[96]; /* what was evaluated, naming the length it uses */
  double value;     /* [s] */
  PetscBool inner;  /* from a solid_internal module: bounds the solid sub-step */
} dt_limit;

typedef struct dt_limits {
  int n;
  dt_limit item[DT_LIMITS_MAX];
} dt_limits;

PetscErrorCode dt_limits_add(dt_limits *l, const char *name, const char *formula, double value);
/* Smallest limit and its index, or +inf / -1 when there is none. */
double dt_limits_min(const dt_limits *l, int *which);

#endif
