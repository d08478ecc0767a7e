/* Diagnostic CSV files of the scenes (flap.csv, cantilever.csv,
 * intestine.csv), written by rank 0 at output times, first column t [s].
 *
 * A fresh run creates the file and writes its header. A restarted run
 * continues it: the header and the rows with t up to the checkpoint's time
 * are kept (rows an interrupted run wrote after its last checkpoint are
 * dropped, the continued run writes them again; so are rows at the
 * checkpoint's time of a diagnostic that had not sampled at that step: the
 * final output of the run that ended there), then rows are appended. A
 * restart into a directory without the file starts it with the header. */
#ifndef DMHS_CSV_H
#define DMHS_CSV_H
#include <stdio.h>
#include <petscsys.h>

struct sim;

/* Rank 0: opens <output_dir>/<name> as above; header (one or more lines, each
 * ending in '\n') is written only when the file is started. Other ranks get NULL. */
PetscErrorCode csv_open(struct sim *s, const char *name, const char *header, FILE **out);
/* The same for a file whose first column is not t (dt.csv: the step): a
 * restart keeps the rows whose first field is <= keep. */
PetscErrorCode csv_open_keeping(struct sim *s, const char *name, const char *header, double keep,
                                FILE **out);
/* Rank 0: writes one row (printf format, ending in '\n') and flushes it. A
 * non-finite value in the row (nan, inf) is refused, naming the file, the
 * column and the row, before anything is written; a failed write or flush is
 * an error naming the file (disk full). */
PetscErrorCode csv_row(FILE *f, const char *name, const char *format, ...)
    PETSC_ATTRIBUTE_FORMAT(3, 4);
/* The same for a row already formatted. */
PetscErrorCode csv_line(FILE *f, const char *name, const char *line);
/* Closes (NULL is a no-op); a failed close is an error naming the file. */
PetscErrorCode csv_close(FILE **f, const char *name);

#endif
