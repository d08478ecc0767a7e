/* Files written whole or not at all (src/io/whole_file.c). Proves:
 *   - a committed file holds exactly what was written, and replaces an older one;
 *     no <path>.tmp is left;
 *   - a commit after a failed write (ok = 0) fails with PETSC_ERR_FILE_WRITE, leaves the
 *     older file as it was and removes the temporary;
 *   - a path in a directory that does not exist fails at the open with
 *     PETSC_ERR_FILE_OPEN, and so does committing a file that is not open. */
#include <unistd.h>
#include "unit_common.h"
#include "dmhs/whole_file.h"

static void read_back(const char *path, char *buf, size_t len) {
  FILE *f = fopen(path, "r");
  assert_non_null(f);
  const size_t n = fread(buf, 1, len - 1, f);
  buf[n] = 0;
  fclose(f);
}

static void test_commit_and_refuse(void **state) {
  (void)state;
  char dir[] = "/tmp/dmhs-whole-file-XXXXXX", path[256], tmp[264], buf[64];
  assert_non_null(mkdtemp(dir));
  snprintf(path, sizeof(path), "%s/summary.csv", dir);
  snprintf(tmp, sizeof(tmp), "%s.tmp", path);
  whole_file w;
  OK(whole_file_open(&w, path, NULL));
  assert_true(fprintf(w.f, "key,value\na,1\n") > 0);
  OK(whole_file_commit(&w, 1, NULL));
  read_back(path, buf, sizeof(buf));
  assert_string_equal(buf, "key,value\na,1\n");
  assert_int_not_equal(access(tmp, F_OK), 0);
  /* a newer version replaces it */
  OK(whole_file_open(&w, path, NULL));
  assert_true(fprintf(w.f, "key,value\na,2\n") > 0);
  OK(whole_file_commit(&w, 1, NULL));
  read_back(path, buf, sizeof(buf));
  assert_string_equal(buf, "key,value\na,2\n");
  /* a failed write: the older file stays, the temporary goes */
  OK(whole_file_open(&w, path, "-dump_final"));
  assert_true(fprintf(w.f, "half a fi") > 0);
  assert_int_equal(whole_file_commit(&w, 0, "-dump_final"), PETSC_ERR_FILE_WRITE);
  read_back(path, buf, sizeof(buf));
  assert_string_equal(buf, "key,value\na,2\n");
  assert_int_not_equal(access(tmp, F_OK), 0);
  assert_int_equal(whole_file_commit(&w, 1, NULL), PETSC_ERR_ARG_WRONGSTATE);
  unlink(path);
  rmdir(dir);
}

static void test_missing_directory(void **state) {
  (void)state;
  whole_file w;
  assert_int_equal(whole_file_open(&w, "/nonexistent-dmhs-dir/summary.csv", NULL),
                   PETSC_ERR_FILE_OPEN);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_commit_and_refuse),
      cmocka_unit_test(test_missing_directory),
  };
  return cmocka_run_group_tests(tests, unit_petsc_setup, unit_petsc_teardown);
}
