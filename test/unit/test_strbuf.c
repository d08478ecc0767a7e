/* strbuf_cat (src/core/strbuf.c). Proves:
 *   - appends fill the buffer up to its last byte (the NUL), in order;
 *   - an append that does not fit, by one byte or more, is PETSC_ERR_ARG_SIZ
 *     and leaves the buffer and the bytes after it as they were;
 *   - a buffer without a NUL in its size is refused, not read past;
 *   - an empty or NULL string appends nothing, also to a full buffer. */
#include <string.h>
#include "unit_common.h"
#include "dmhs/strbuf.h"

static void test_fill(void **state) {
  (void)state;
  char buf[8] = "";
  OK(strbuf_cat(buf, sizeof(buf), "abc"));
  OK(strbuf_cat(buf, sizeof(buf), ", "));
  assert_string_equal(buf, "abc, ");
  OK(strbuf_cat(buf, sizeof(buf), "de")); /* 7 characters and the NUL: full */
  assert_string_equal(buf, "abc, de");
  OK(strbuf_cat(buf, sizeof(buf), ""));
  OK(strbuf_cat(buf, sizeof(buf), NULL));
  assert_string_equal(buf, "abc, de");
  /* longer than half the buffer, into an empty one (PETSc 3.18's PetscStrlcat
   * copies only size - strlen(src) characters of it) */
  char one[8] = "";
  OK(strbuf_cat(one, sizeof(one), "abcdefg"));
  assert_string_equal(one, "abcdefg");
}

static void test_too_long(void **state) {
  (void)state;
  char mem[16];
  memset(mem, '#', sizeof(mem));
  char *buf = mem + 4; /* 8 bytes, guarded on both sides */
  buf[0] = 0;
  OK(strbuf_cat(buf, 8, "abcd"));
  assert_int_equal(strbuf_cat(buf, 8, "efgh"), PETSC_ERR_ARG_SIZ); /* one byte short */
  assert_string_equal(buf, "abcd");
  assert_int_equal(strbuf_cat(buf, 8, "a string much longer than the buffer"), PETSC_ERR_ARG_SIZ);
  assert_string_equal(buf, "abcd");
  OK(strbuf_cat(buf, 8, "efg"));
  assert_string_equal(buf, "abcdefg");
  assert_int_equal(strbuf_cat(buf, 8, "h"), PETSC_ERR_ARG_SIZ);
  assert_string_equal(buf, "abcdefg");
  for (int k = 0; k < 4; k++)
    assert_int_equal(mem[k], '#');
  for (int k = 12; k < 16; k++)
    assert_int_equal(mem[k], '#');
}

static void test_unterminated(void **state) {
  (void)state;
  char mem[8];
  memset(mem, 'x', sizeof(mem));
  mem[7] = 0;
  assert_int_equal(strbuf_cat(mem, 4, "y"), PETSC_ERR_ARG_SIZ);
  assert_int_equal(strbuf_cat(mem, 4, ""), PETSC_ERR_ARG_SIZ);
  assert_int_equal(strbuf_cat(mem, 0, "y"), PETSC_ERR_ARG_SIZ);
  assert_string_equal(mem, "xxxxxxx");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_fill),
      cmocka_unit_test(test_too_long),
      cmocka_unit_test(test_unterminated),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
