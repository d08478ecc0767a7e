/* A file written whole or not at all (summaries, profiles, the XDMF index, the final dump):
 * the text goes to <path>.tmp, which replaces <path> only once every write and the close
 * succeeded, so a reader never sees half a file. A write interrupted by a crash leaves a
 * stale <path>.tmp, which the next run into that directory removes (outdir.h). */
#ifndef DMHS_WHOLE_FILE_H
#define DMHS_WHOLE_FILE_H
#include <stdio.h>
#include <petscsys.h>

typedef struct {
  FILE *f; /* write the text here, then whole_file_commit */
  char path[PETSC_MAX_PATH_LEN];
  char tmp[PETSC_MAX_PATH_LEN + 8];
} whole_file;

/* Opens <path>.tmp for writing; what (an option such as "-dump_final", or NULL) prefixes
 * every message about the file. */
PetscErrorCode whole_file_open(whole_file *w, const char *path, const char *what);
/* Closes the temporary and, when ok (every write into w->f succeeded) and the close did
 * too, renames it over <path>; else removes it and fails naming the file. */
PetscErrorCode whole_file_commit(whole_file *w, int ok, const char *what);

#endif
