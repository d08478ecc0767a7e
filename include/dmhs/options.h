/* Checked option readers: every value is validated where it is read, by name.
 *
 * Modules and scenes read their options with the options_read_* macros below inside
 * PetscOptionsBegin/End (the arguments of PETSc's PetscOptionsReal, Int, Bool, String,
 * Enum, RealArray, StringArray) and with options_get_* outside it (those of
 * PetscOptionsGetReal, GetInt, GetBool). Each looks at the option's text in the database
 * first and refuses, in one line naming the option, the value and what is allowed:
 *   - an option given without a value where one is needed (`-dt` last on the line);
 *   - a real that is not a number (`-dt garbage`) or not finite (inf, nan);
 *   - an integer that is not one (`-channel_nx 2.5`) or out of range;
 *   - a boolean other than true/false/yes/no/on/off/1/0;
 *   - an enumeration value not in its list;
 *   - an array with more values than the option takes (`-body_force 1e-4,0,0`)
 *     or with a bad element;
 * then calls PETSc's reader and records the value (-help, checkpoints). Ranges (h > 0, ...)
 * stay with the module that knows them. src/core/options.c. */
#ifndef DMHS_OPTIONS_H
#define DMHS_OPTIONS_H
#include <petscsys.h>

PetscErrorCode options_real(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], PetscReal current, PetscReal *value, PetscBool *set);
PetscErrorCode options_int(PetscOptionItems *po, const char opt[], const char text[],
                           const char man[], PetscInt current, PetscInt *value, PetscBool *set,
                           PetscInt lb, PetscInt ub);
PetscErrorCode options_bool(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], PetscBool current, PetscBool *value, PetscBool *set);
PetscErrorCode options_string(PetscOptionItems *po, const char opt[], const char text[],
                              const char man[], const char current[], char *value, size_t len,
                              PetscBool *set);
PetscErrorCode options_enum(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], const char *const *list, PetscEnum current,
                            PetscEnum *value, PetscBool *set);
PetscErrorCode options_real_array(PetscOptionItems *po, const char opt[], const char text[],
                                  const char man[], PetscReal value[], PetscInt *n, PetscBool *set);
PetscErrorCode options_string_array(PetscOptionItems *po, const char opt[], const char text[],
                                    const char man[], char *value[], PetscInt *n, PetscBool *set);
PetscErrorCode options_get_real(PetscOptions options, const char pre[], const char opt[],
                                PetscReal *value, PetscBool *set);
PetscErrorCode options_get_int(PetscOptions options, const char pre[], const char opt[],
                               PetscInt *value, PetscBool *set);
PetscErrorCode options_get_bool(PetscOptions options, const char pre[], const char opt[],
                                PetscBool *value, PetscBool *set);

/* Marks an option as run control, where it is registered (after its reader): when and where
 * output goes, how long to run, checks that do not change the state. Such an option may
 * differ between a run and its restart, and a checkpoint does not store it. */
PetscErrorCode options_run_control(const char *name);
/* Every value the readers returned is recorded (the last one per option).
 * options_physics: "name value\n" lines, sorted, of the recorded options that
 * are not marked run control: what a checkpoint stores. PetscFree it. */
PetscErrorCode options_physics(char **text);
/* The differences between a stored options_physics text and the current one,
 * "-name X in the checkpoint, Y now; ..." in report, and how many. An option this run
 * reads at its default (not given) that the stored text lacks is not a difference: the
 * checkpoint's dmhs had no such option. Those go to added ("-name value; ..."), counted
 * in n_added. */
PetscErrorCode options_compare_physics(const char *stored, char *report, size_t len, int *n_changed,
                                       char *added, size_t added_len, int *n_added);
/* For an option nobody read (name with its leading '-'): the recorded option names closest
 * to it (up to three as close as the closest) by edit distance, or else that it starts or
 * that start it, as "-a, -b or -c" in out; "" when none is close. */
PetscErrorCode options_nearest(const char *name, char *out, size_t len);
/* Clears the record (sim_destroy). */
void options_forget(void);
/* -help: from now on the recorded values stay (those of the chosen scene, read
 * first); options first read later are listed with `note` (static text). */
void options_help_freeze(const char *note);
/* -help: every recorded option once, by section in the order first read:
 * "-name <value as this run would use it>  description". */
PetscErrorCode options_help_print(MPI_Comm comm);

/* Inside PetscOptionsBegin/End, with the arguments of PETSc's reader of the same kind */
#define options_read_real(opt, text, man, current, value, set)                                     \
  options_real(PetscOptionsObject, opt, text, man, current, value, set)
#define options_read_int(opt, text, man, current, value, set)                                      \
  options_int(PetscOptionsObject, opt, text, man, current, value, set, PETSC_MIN_INT, PETSC_MAX_INT)
#define options_read_bool(opt, text, man, current, value, set)                                     \
  options_bool(PetscOptionsObject, opt, text, man, current, value, set)
#define options_read_string(opt, text, man, current, value, len, set)                              \
  options_string(PetscOptionsObject, opt, text, man, current, value, len, set)
#define options_read_enum(opt, text, man, list, current, value, set)                               \
  options_enum(PetscOptionsObject, opt, text, man, list, current, value, set)
#define options_read_real_array(opt, text, man, value, n, set)                                     \
  options_real_array(PetscOptionsObject, opt, text, man, value, n, set)
#define options_read_string_array(opt, text, man, value, n, set)                                   \
  options_string_array(PetscOptionsObject, opt, text, man, value, n, set)

#endif
