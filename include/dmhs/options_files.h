/* Options files that include others (src/driver/options_files.c), before PETSc
 * reads the command line.
 *
 * PETSc reads `-options_file X` itself, and opens a `-options_file Y` line
 * inside X relative to the working directory: a run started elsewhere with an
 * absolute path to X fails. options_files_resolve reads the command line's
 * options files first; a relative Y that is not there is looked for in X's
 * directory and then in each directory above it (the shipped inputs name their
 * base input from the repository root: `-options_file input/vein.opts`), and
 * the first found is used. Only a file with such an include changes hands: its
 * lines go to PETSc as the command-line words `-name value` in its place (the
 * same options in the same order), the include as `-options_file <found>`.
 * Every other file, and any file with a line PETSc would refuse, PETSc reads
 * as before, with its own messages. An include found nowhere stays as written;
 * PETSc's "Unable to open options file Y" then gets the file and line that
 * include Y (options_files_explain). Plain C: no PETSc call. */
#ifndef DMHS_OPTIONS_FILES_H
#define DMHS_OPTIONS_FILES_H
#include <stddef.h>

/* Replaces *argv (argc words, argv[argc] == NULL) by the command line PETSc is
 * to read, as above; keeps it when nothing needs resolving. Returns 0, or -1
 * when out of memory (the command line is then kept). */
int options_files_resolve(int *argc, char ***argv);
/* message, completed for an options file that cannot be opened: the file and
 * line that include it and where it was looked for. */
void options_files_explain(const char *message, char *out, size_t len);
/* Frees what options_files_resolve allocated (after PetscFinalize). */
void options_files_free(void);

#endif
