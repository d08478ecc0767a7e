/* Shared bits of the cmocka unit tests: cmocka headers, PETSc set-up as a
 * group fixture (with the event registry and a returning error handler, so a
 * failing PETSc call gives an error code the test can check instead of
 * aborting), a check macro and a small deterministic random generator. */
#ifndef DMHS_UNIT_COMMON_H
#define DMHS_UNIT_COMMON_H
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <math.h>
#include <cmocka.h>
#include <petscsys.h>
#include "dmhs/events.h"
#include "dmhs/fields.h"

/* A PETSc call that must succeed. */
#define OK(call) assert_int_equal((int)(call), 0)

/* |a - b| <= tol, with both values in the failure message. */
#define assert_close(a, b, tol)                                                                    \
  do {                                                                                             \
    const double a_ = (a), b_ = (b), t_ = (tol);                                                   \
    if (!(fabs(a_ - b_) <= t_))                                                                    \
      fail_msg("%s = %.17g vs %s = %.17g: |diff| %.3e > %.3e", #a, a_, #b, b_, fabs(a_ - b_), t_); \
  } while (0)

/* The SPH module's fields (drho, p: it enables them in its options pass), for the tests
 * that drive SPH sweeps, the integrator or the state check without the module. */
static inline PetscErrorCode unit_enable_sph_fields(void) {
  const PetscErrorCode e = fields_enable("drho");
  return e ? e : fields_enable("p");
}

static inline int unit_petsc_setup(void **state) {
  (void)state;
  if (PetscInitializeNoArguments())
    return -1;
  if (events_register())
    return -1;
  if (PetscPushErrorHandler(PetscReturnErrorHandler, NULL))
    return -1;
  return 0;
}

static inline int unit_petsc_teardown(void **state) {
  (void)state;
  PetscPopErrorHandler();
  return PetscFinalize() ? -1 : 0;
}

/* splitmix64: uniform doubles in [0, 1), the same sequence on every machine. */
typedef struct {
  uint64_t s;
} unit_rng;
static inline double unit_uniform(unit_rng *g) {
  uint64_t z = (g->s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return (double)(z >> 11) * 0x1.0p-53;
}
static inline double unit_range(unit_rng *g, double lo, double hi) {
  return lo + (hi - lo) * unit_uniform(g);
}

#endif
