/* The diagnostic list (src/diag/diagnostics.c) and the diagnostics' part of
 * checkpoints (src/io/checkpoint.c). Proves:
 *   - the schedule: every N steps (step 0 included), at output times (step 0
 *     and, by the driver's schedule, t within dt/2 of next_output_t),
 *     not_at_start, a diagnostic's own due hook, and their union;
 *   - diagnostics_sample runs the due ones only, in registration order, and
 *     diagnostics_finish every finish in that order;
 *   - a second diagnostic of a name, a name that would nest in the checkpoint
 *     and a diagnostic without sample are refused;
 *   - a checkpoint round trip: each diagnostic's state comes back under its own
 *     name (two diagnostics storing a dataset of the same name do not mix), and
 *     a checkpoint without a registered diagnostic's group is refused naming it. */
#include <unistd.h>
#include "unit_common.h"
#include "dmhs/sim.h"
#include "dmhs/scene.h"
#include "dmhs/io.h"
#include "dmhs/diagnostics.h"
#include "dmhs/checkpoint.h"
#include "dmhs/run_control.h"

/* what the test diagnostics did, in order: 'A' + index for a sample, 'a' + index for a finish */
static char trace[64];
static int n_trace;

typedef struct {
  int index;
  PetscInt64 counter; /* the state a restart needs */
  PetscInt due_step;  /* the own due hook's step, -1 = none */
} probe;

static PetscErrorCode probe_sample(diagnostic *self, sim *s) {
  probe *p = self->data;
  (void)s;
  trace[n_trace++] = (char)('A' + p->index);
  p->counter++;
  return 0;
}

static PetscErrorCode probe_finish(diagnostic *self, sim *s) {
  probe *p = self->data;
  (void)s;
  trace[n_trace++] = (char)('a' + p->index);
  return 0;
}

static PetscBool probe_due(const diagnostic *self, const sim *s) {
  const probe *p = self->data;
  return s->step == p->due_step ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode probe_destroy(diagnostic *self) {
  return PetscFree(self->data);
}

static PetscErrorCode probe_write(diagnostic *self, sim *s, checkpoint_io *io) {
  const probe *p = self->data;
  (void)s;
  return checkpoint_put_ints(io, "counter", &p->counter, 1);
}

static PetscErrorCode probe_read(diagnostic *self, sim *s, checkpoint_io *io) {
  probe *p = self->data;
  (void)s;
  return checkpoint_get_ints(io, "counter", &p->counter, 1);
}

static diagnostic *probe_add(sim *s, const char *name, int index, diagnostic_schedule when) {
  diagnostic *d;
  probe *p;
  OK(diagnostic_create(name, &d));
  OK(PetscNew(&p));
  p->index = index;
  p->due_step = -1;
  d->data = p;
  d->when = when;
  d->due = probe_due;
  d->sample = probe_sample;
  d->finish = probe_finish;
  d->destroy = probe_destroy;
  d->checkpoint_write = probe_write;
  d->checkpoint_read = probe_read;
  OK(diagnostics_add(s, d));
  return d;
}

static scene test_scene = {.name = "test"};
static io_state test_io;
static run_control test_schedule_rc = {.output_interval = 0.5, .next_output_t = 0.5};

static void make_sim(sim *s) {
  OK(PetscMemzero(s, sizeof(*s)));
  s->comm = PETSC_COMM_SELF;
  s->size = 1;
  s->scene_name = test_scene.name;
  s->io = &test_io;
  s->dt = 0.1;
}

/* sets step, t and whether the state is an output, as the driver does (step 0 always) */
static void at_time(sim *s, PetscInt step, double t) {
  s->step = step;
  s->t = t;
  s->output_step = step == 0 || run_control_output_due(&test_schedule_rc, s);
}

/* sets step and t = step dt */
static void at_step(sim *s, PetscInt step) {
  at_time(s, step, (double)step * s->dt);
}

static void test_schedule(void **state) {
  (void)state;
  static sim s;
  make_sim(&s);
  diagnostic *every3 = probe_add(&s, "every3", 0, (diagnostic_schedule){.every_steps = 3});
  diagnostic *outputs =
      probe_add(&s, "outputs", 1, (diagnostic_schedule){.at_outputs = PETSC_TRUE});
  diagnostic *late = probe_add(
      &s, "late", 2, (diagnostic_schedule){.at_outputs = PETSC_TRUE, .not_at_start = PETSC_TRUE});
  diagnostic *own = probe_add(&s, "own", 3, (diagnostic_schedule){0});
  ((probe *)own->data)->due_step = 2;
  diagnostic *both =
      probe_add(&s, "both", 4, (diagnostic_schedule){.every_steps = 4, .at_outputs = PETSC_TRUE});
  /* steps 0..8 at dt = 0.1 with the next output at t = 0.5 (step 5): which is due */
  for (PetscInt step = 0; step <= 8; step++) {
    at_step(&s, step);
    const PetscBool out = step == 0 || step >= 5 ? PETSC_TRUE : PETSC_FALSE; /* t >= 0.45 */
    assert_int_equal(diagnostic_output_time(&s), out);
    assert_int_equal(diagnostic_is_due(every3, &s), step % 3 == 0);
    assert_int_equal(diagnostic_is_due(outputs, &s), out);
    assert_int_equal(diagnostic_is_due(late, &s), out && step > 0);
    assert_int_equal(diagnostic_is_due(own, &s), step == 2);
    assert_int_equal(diagnostic_is_due(both, &s), out || step % 4 == 0);
  }
  /* just before the output time by more than dt/2: not yet */
  at_time(&s, 4, 0.5 - 0.051);
  assert_false(diagnostic_is_due(outputs, &s));
  at_time(&s, 4, 0.5 - 0.049);
  assert_true(diagnostic_is_due(outputs, &s));
  /* lookup */
  at_step(&s, 0);
  assert_ptr_equal(diagnostics_find(&s, "own"), own);
  assert_null(diagnostics_find(&s, "none"));
  OK(diagnostics_destroy(&s));
  assert_int_equal(s.n_diagnostics, 0);
}

static void test_order(void **state) {
  (void)state;
  static sim s;
  make_sim(&s);
  n_trace = 0;
  diagnostic *a = probe_add(&s, "first", 0, (diagnostic_schedule){.every_steps = 2});
  probe_add(&s, "second", 1, (diagnostic_schedule){.every_steps = 1});
  probe_add(&s, "third", 2, (diagnostic_schedule){.every_steps = 3});
  for (PetscInt step = 0; step <= 3; step++) {
    at_step(&s, step);
    OK(diagnostics_sample(&s));
  }
  OK(diagnostics_finish(&s));
  trace[n_trace] = 0;
  /* step 0: all; 1: second; 2: first, second; 3: second, third; then every finish */
  assert_string_equal(trace, "ABCBABBCabc");
  assert_int_equal(((probe *)a->data)->counter, 2);
  OK(diagnostics_destroy(&s));
}

static void test_refused(void **state) {
  (void)state;
  static sim s;
  diagnostic *d;
  make_sim(&s);
  probe_add(&s, "once", 0, (diagnostic_schedule){.every_steps = 1});
  OK(diagnostic_create("once", &d));
  d->sample = probe_sample;
  assert_int_not_equal(diagnostics_add(&s, d), 0);
  OK(PetscFree(d));
  OK(diagnostic_create("no_sample", &d));
  assert_int_not_equal(diagnostics_add(&s, d), 0);
  OK(PetscFree(d));
  assert_int_not_equal(diagnostic_create("a/b", &d), 0);
  assert_int_not_equal(diagnostic_create("", &d), 0);
  assert_int_equal(s.n_diagnostics, 1);
  OK(diagnostics_destroy(&s));
}

/* a sim with three particles, for checkpoint_write / checkpoint_read */
static void make_particles(sim *s) {
  fields_reset();
  OK(particles_create(&s->ps));
  const double x[2] = {0.1, 0.2}, v[2] = {0, 0};
  for (int k = 0; k < 3; k++)
    OK(particles_add_owned(&s->ps, k, PTYPE_FLUID, x, v, 1.0, 1000.0, NULL));
  s->substeps.n = 1;
}

static void test_checkpoint_round_trip(void **state) {
  (void)state;
  static sim s;
  char path[] = "/tmp/dmhs-test-diagnostic-XXXXXX";
  const int fd = mkstemp(path);
  assert_true(fd >= 0);
  close(fd);
  make_sim(&s);
  make_particles(&s);
  diagnostic *a = probe_add(&s, "alpha", 0, (diagnostic_schedule){.every_steps = 1});
  diagnostic *b = probe_add(&s, "beta", 1, (diagnostic_schedule){.every_steps = 1});
  ((probe *)a->data)->counter = 7;
  ((probe *)b->data)->counter = -3; /* the same dataset name, another group */
  OK(checkpoint_write(&s, path));
  ((probe *)a->data)->counter = 0;
  ((probe *)b->data)->counter = 0;
  OK(checkpoint_read(&s, path));
  assert_int_equal(((probe *)a->data)->counter, 7);
  assert_int_equal(((probe *)b->data)->counter, -3);
  /* a diagnostic the checkpoint does not know: refused */
  probe_add(&s, "gamma", 2, (diagnostic_schedule){.every_steps = 1});
  assert_int_not_equal(checkpoint_read(&s, path), 0);
  OK(diagnostics_destroy(&s));
  OK(particles_destroy(&s.ps));
  unlink(path);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_schedule),
      cmocka_unit_test(test_order),
      cmocka_unit_test(test_refused),
      cmocka_unit_test(test_checkpoint_round_trip),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
