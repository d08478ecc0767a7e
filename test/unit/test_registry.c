/* The registry of scenes (src/driver/registry.c), the physics modules by name
 * (src/physics/modules.c) and modules_enable. Proves:
 *   - every scene and module the solver documents is registered under its
 *     name and creates an object of that name with the callbacks the step
 *     loop calls; the interaction needs of the pair and bonded modules;
 *   - an unknown scene or module is an error, not a NULL object;
 *   - registry_scene_names lists the scenes in order, in a buffer of exactly
 *     the length needed, and refuses a buffer too small without writing past it;
 *   - initialize twice is harmless, finalize then initialize works again;
 *   - modules_enable adds a module once and refuses it twice. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/registry.h"
#include "dmhs/sim.h"
#include "dmhs/modules.h"

static const char *const scene_names[] = {"poiseuille", "couette",   "box",  "cantilever",
                                          "flap",       "intestine", "vein", "peristaltic_channel"};
static const char *const module_names[] = {
    "sph",       "body_force", "bond_harmonic", "bond_nonlinear", "angle_harmonic",
    "repulsion", "solid_load", "peristalsis",   "agglomeration",  "wall_wave"};
#define N_SCENES  (sizeof(scene_names) / sizeof(scene_names[0]))
#define N_MODULES (sizeof(module_names) / sizeof(module_names[0]))

static int setup(void **state) {
  if (unit_petsc_setup(state))
    return -1;
  return registry_initialize() ? -1 : 0;
}

static int teardown(void **state) {
  if (registry_finalize())
    return -1;
  return unit_petsc_teardown(state);
}

static void destroy_module(module *m) {
  OK(m->destroy(m));
  OK(PetscFree(m));
}

static void test_modules(void **state) {
  (void)state;
  for (size_t k = 0; k < N_MODULES; k++) {
    module *m = NULL;
    OK(modules_create(module_names[k], &m));
    assert_non_null(m);
    assert_string_equal(m->name, module_names[k]);
    assert_non_null(m->set_from_options);
    assert_non_null(m->compute);
    assert_non_null(m->destroy);
    destroy_module(m);
  }
  /* what the step loop and the ghost width depend on */
  struct {
    const char *name;
    unsigned needs;
    PetscBool solid_internal;
  } want[] = {{"sph", MODULE_NEEDS_PAIRS, PETSC_FALSE},
              {"repulsion", MODULE_NEEDS_PAIRS, PETSC_FALSE},
              {"bond_harmonic", MODULE_NEEDS_BONDS, PETSC_TRUE},
              {"bond_nonlinear", MODULE_NEEDS_BONDS, PETSC_TRUE},
              {"angle_harmonic", MODULE_NEEDS_ANGLES, PETSC_TRUE},
              {"body_force", 0, PETSC_FALSE},
              {"peristalsis", 0, PETSC_FALSE}};
  for (size_t k = 0; k < sizeof(want) / sizeof(want[0]); k++) {
    module *m;
    OK(modules_create(want[k].name, &m));
    if (m->needs != want[k].needs)
      fail_msg("module %s: needs 0x%x, expected 0x%x", m->name, m->needs, want[k].needs);
    assert_int_equal(m->solid_internal, want[k].solid_internal);
    destroy_module(m);
  }
}

static void test_unknown_names(void **state) {
  (void)state;
  module *m = NULL;
  scene *s = NULL;
  assert_int_equal(modules_create("sph2", &m), PETSC_ERR_ARG_UNKNOWN_TYPE);
  assert_null(m);
  assert_int_equal(modules_create("", &m), PETSC_ERR_ARG_UNKNOWN_TYPE);
  assert_int_equal(registry_create_scene("intestin", &s), PETSC_ERR_ARG_UNKNOWN_TYPE);
  assert_null(s);
}

static void test_scenes(void **state) {
  (void)state;
  for (size_t k = 0; k < N_SCENES; k++) {
    scene *s = NULL;
    OK(registry_create_scene(scene_names[k], &s));
    assert_non_null(s);
    assert_string_equal(s->name, scene_names[k]);
    assert_non_null(s->set_from_options);
    assert_non_null(s->build);
    assert_non_null(s->destroy);
    OK(s->destroy(s));
    OK(PetscFree(s));
  }
}

static void test_scene_names(void **state) {
  (void)state;
  char buf[256];
  OK(registry_scene_names(buf, sizeof(buf)));
  assert_string_equal(buf, "poiseuille, couette, box, cantilever, flap, intestine, vein, "
                           "peristaltic_channel");
  /* exactly big enough: the whole list */
  const size_t need = strlen(buf) + 1;
  char exact[128];
  assert_true(need <= sizeof(exact));
  OK(registry_scene_names(exact, need));
  assert_string_equal(exact, buf);
  /* one byte short, or much too small: an error, nothing written past the buffer */
  memset(exact, 'x', sizeof(exact));
  assert_int_equal(registry_scene_names(exact, need - 1), PETSC_ERR_ARG_SIZ);
  assert_string_equal(exact, "poiseuille, couette, box, cantilever, flap, intestine, vein, ");
  assert_int_equal(exact[need - 1], 'x');
  memset(exact, 'x', sizeof(exact));
  assert_int_equal(registry_scene_names(exact, 12), PETSC_ERR_ARG_SIZ);
  assert_string_equal(exact, "poiseuille");
  assert_int_equal(exact[12], 'x');
}

static void test_initialize_finalize(void **state) {
  (void)state;
  module *m;
  OK(registry_initialize()); /* again: harmless */
  OK(modules_create("sph", &m));
  destroy_module(m);
  OK(registry_finalize());
  OK(registry_initialize());
  OK(modules_create("body_force", &m));
  destroy_module(m);
}

static void test_enable_module(void **state) {
  (void)state;
  static sim s;
  module *m = NULL, *again = NULL;
  OK(PetscMemzero(&s, sizeof(s)));
  s.comm = PETSC_COMM_SELF;
  OK(modules_enable(&s, "body_force", &m));
  assert_int_equal(s.n_modules, 1);
  assert_true(s.modules[0] == m);
  OK(modules_enable(&s, "peristalsis", NULL));
  assert_int_equal(s.n_modules, 2);
  assert_string_equal(s.modules[1]->name, "peristalsis");
  assert_int_equal(modules_enable(&s, "body_force", &again), PETSC_ERR_PLIB);
  assert_int_equal(s.n_modules, 2);
  assert_int_equal(modules_enable(&s, "no_module", &again), PETSC_ERR_ARG_UNKNOWN_TYPE);
  assert_int_equal(s.n_modules, 2);
  for (int k = 0; k < s.n_modules; k++)
    destroy_module(s.modules[k]);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_modules),
      cmocka_unit_test(test_unknown_names),
      cmocka_unit_test(test_scenes),
      cmocka_unit_test(test_scene_names),
      cmocka_unit_test(test_initialize_finalize),
      cmocka_unit_test(test_enable_module),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
