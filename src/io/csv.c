/* Diagnostic CSV files of the scenes: open for a fresh or a restarted run
 * (see csv.h). The rewrite on restart goes through <name>.tmp and a rename,
 * so an interrupted rewrite never leaves half a file. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/csv.h"

/* Is this line a data row with t (its first field) after t_keep? Header and
 * comment lines (no number first) are kept. */
static int csv_row_after(const char *line, double t_keep) {
  char *end;
  const double t = strtod(line, &end);
  if (end == line || (*end != ',' && *end != '\n' && *end != 0))
    return 0;
  return t > t_keep;
}

/* Keeps the header and the rows up to t_keep of path; returns 0 or an errno. */
static int csv_truncate(const char *path, const char *tmp, double t_keep, int *found) {
  char line[4096];
  FILE *in = fopen(path, "r");
  *found = in != NULL;
  if (!in)
    return errno == ENOENT ? 0 : errno;
  FILE *out = fopen(tmp, "w");
  if (!out) {
    const int err = errno;
    fclose(in);
    return err;
  }
  int ok = 1, at_line_start = 1, drop = 0;
  while (ok && fgets(line, sizeof(line), in)) {
    /* a line longer than the buffer arrives in pieces: decide on its first */
    if (at_line_start)
      drop = csv_row_after(line, t_keep);
    at_line_start = strchr(line, '\n') != NULL;
    if (!drop)
      ok = fputs(line, out) >= 0;
  }
  ok = ok && !ferror(in);
  fclose(in);
  ok = fclose(out) == 0 && ok;
  if (!ok) {
    unlink(tmp);
    return EIO;
  }
  return rename(tmp, path) ? errno : 0;
}

PetscErrorCode csv_open(sim *s, const char *name, const char *header, FILE **out) {
  /* rows at the checkpoint's time belong to the run only if its diagnostic sampled there:
   * otherwise they are the final output of a run that stopped at the checkpoint */
  const double keep = s->io->restart_t + (s->io->csv_keep_restart_rows ? 0.5 : -0.5) * s->dt;
  PetscFunctionBeginUser;
  PetscCall(csv_open_keeping(s, name, header, keep, out));
  PetscFunctionReturn(0);
}

PetscErrorCode csv_open_keeping(sim *s, const char *name, const char *header, double keep,
                                FILE **out) {
  char path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN + 8];
  int found = 0;
  PetscFunctionBeginUser;
  *out = NULL;
  if (s->rank)
    PetscFunctionReturn(0);
  PetscCall(io_output_path(s, name, path, sizeof(path)));
  if (s->io->restarted) {
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
    const int err = csv_truncate(path, tmp, keep, &found);
    PetscCheck(
        !err, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
        "cannot continue %s after the restart (keeping its rows with a first field up to %g): %s",
        path, keep, strerror(err));
  }
  *out = fopen(path, found ? "a" : "w");
  PetscCheck(*out, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path,
             strerror(errno));
  if (!found)
    PetscCall(csv_line(*out, path, header));
  PetscFunctionReturn(0);
}

/* 0, or the 1-based column of the first field that reads as a non-finite number */
static int csv_nonfinite_column(const char *line) {
  int column = 1;
  for (const char *c = line; *c; column++) {
    char *end;
    const double v = strtod(c, &end);
    if (end != c && (*end == ',' || *end == '\n' || *end == 0) && !isfinite(v))
      return column;
    while (*c && *c != ',')
      c++;
    if (*c == ',')
      c++;
  }
  return 0;
}

PetscErrorCode csv_line(FILE *f, const char *name, const char *line) {
  const int column = csv_nonfinite_column(line);
  PetscFunctionBeginUser;
  PetscCheck(!column, PETSC_COMM_SELF, PETSC_ERR_FP,
             "refusing to write a non-finite value to %s: column %d of the row %.200s", name,
             column, line);
  PetscCheck(fputs(line, f) >= 0 && fflush(f) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "writing %s failed: %s (disk full?)", name, strerror(errno ? errno : EIO));
  PetscFunctionReturn(0);
}

PetscErrorCode csv_row(FILE *f, const char *name, const char *format, ...) {
  char small[1024], *line = small;
  va_list ap;
  PetscFunctionBeginUser;
  va_start(ap, format);
  const int n = vsnprintf(small, sizeof(small), format, ap);
  va_end(ap);
  PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cannot format a row of %s", name);
  if ((size_t)n >= sizeof(small)) {
    PetscCall(PetscMalloc1((size_t)n + 1, &line));
    va_start(ap, format);
    vsnprintf(line, (size_t)n + 1, format, ap);
    va_end(ap);
  }
  PetscErrorCode err = csv_line(f, name, line);
  if (line != small)
    PetscCall(PetscFree(line));
  PetscCall(err);
  PetscFunctionReturn(0);
}

PetscErrorCode csv_close(FILE **f, const char *name) {
  PetscFunctionBeginUser;
  if (*f) {
    const int failed = fclose(*f);
    *f = NULL;
    PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "closing %s failed: %s (disk full?)",
               name, strerror(errno));
  }
  PetscFunctionReturn(0);
}
