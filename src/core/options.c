/* Checked option readers (see dmhs/options.h): validate the option's text in
 * the database, naming the option, the value and what it takes, then let
 * PETSc read it. PETSc's own functions are called as (name)(...) so that the
 * macros of options.h do not apply here. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "dmhs/sim.h"
#include "dmhs/options.h"

/* The option's text: *found, and *raw = NULL when it was given without a value. */
static PetscErrorCode options_raw(PetscOptions options, const char pre[], const char opt[],
                                  const char **raw, PetscBool *found) {
  PetscFunctionBeginUser;
  *raw = NULL;
  PetscCall(PetscOptionsFindPair(options, pre, opt, raw, found));
  if (*found && *raw && !(*raw)[0])
    *raw = NULL;
  PetscFunctionReturn(0);
}

/* The whole of t (trailing blanks aside) is a number. */
static int options_parse_real(const char *t, double *v) {
  char *end;
  *v = strtod(t, &end);
  if (end == t)
    return 0;
  while (isspace((unsigned char)*end))
    end++;
  return *end == 0;
}

static int options_parse_int(const char *t, long long *v) {
  char *end;
  errno = 0;
  *v = strtoll(t, &end, 10);
  if (end == t || errno == ERANGE)
    return 0;
  while (isspace((unsigned char)*end))
    end++;
  return *end == 0;
}

static PetscErrorCode options_check_real(MPI_Comm comm, const char opt[], const char raw[],
                                         const char elem[], const char takes[], const char text[]) {
  double v;
  char what[300];
  PetscFunctionBeginUser;
  if (elem == raw)
    what[0] = 0;
  else
    snprintf(what, sizeof(what), "'%s' is ", elem);
  PetscCheck(options_parse_real(elem, &v), comm, PETSC_ERR_ARG_WRONG,
             "%s %s: %snot a number; %s takes %s (%s)", opt, raw, what, opt, takes, text);
  PetscCheck(isfinite(v), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: %snot finite; %s takes %s (%s)", opt, raw, what, opt, takes, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_need_value(MPI_Comm comm, const char opt[], const char *raw,
                                         const char takes[], const char text[]) {
  PetscFunctionBeginUser;
  PetscCheck(raw, comm, PETSC_ERR_ARG_WRONG,
             "option %s was given without a value; it takes %s (%s)", opt, takes, text);
  PetscFunctionReturn(0);
}

/* Comma-separated elements of raw: at most nmax, each checked by kind (0 real, 1 string). */
static PetscErrorCode options_check_list(MPI_Comm comm, const char opt[], const char raw[],
                                         PetscInt nmax, int kind, const char text[]) {
  char takes[96], elem[256];
  PetscInt count = 0;
  PetscFunctionBeginUser;
  snprintf(takes, sizeof(takes), "up to %d %s separated by commas", (int)nmax,
           kind == 0 ? "finite real numbers" : "names");
  for (const char *c = raw;; c++) {
    const char *comma = strchr(c, ',');
    const size_t len = comma ? (size_t)(comma - c) : strlen(c);
    count++;
    PetscCheck(len < sizeof(elem), comm, PETSC_ERR_ARG_WRONG, "%s %s: an element is too long", opt,
               raw);
    memcpy(elem, c, len);
    elem[len] = 0;
    PetscCheck(len > 0, comm, PETSC_ERR_ARG_WRONG, "%s %s: empty element %d; %s takes %s (%s)", opt,
               raw, (int)count, opt, takes, text);
    if (kind == 0)
      PetscCall(options_check_real(comm, opt, raw, elem, takes, text));
    if (!comma)
      break;
    c = comma;
  }
  PetscCheck(count <= nmax, comm, PETSC_ERR_ARG_SIZ, "%s %s: %d values, but %s takes %s (%s)", opt,
             raw, (int)count, opt, takes, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_check_int(MPI_Comm comm, const char opt[], const char *raw,
                                        PetscInt lb, PetscInt ub, const char text[]) {
  long long v;
  PetscFunctionBeginUser;
  PetscCall(options_need_value(comm, opt, raw, "an integer", text));
  PetscCheck(options_parse_int(raw, &v), comm, PETSC_ERR_ARG_WRONG,
             "%s %s: not an integer; %s takes an integer (%s)", opt, raw, opt, text);
  PetscCheck(v >= lb && v <= ub, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s: out of range; %s takes an integer in [%" PetscInt_FMT ", %" PetscInt_FMT
             "] (%s)",
             opt, raw, opt, lb, ub, text);
  PetscFunctionReturn(0);
}

static PetscErrorCode options_check_bool(MPI_Comm comm, const char opt[], const char *raw,
                                         const char text[]) {
  static const char *const words[] = {"1", "0", "true", "false", "yes", "no", "on", "off"};
  PetscFunctionBeginUser;
  if (!raw)
    PetscFunctionReturn(0); /* -quiet alone means true */
  for (size_t k = 0; k < sizeof(words) / sizeof(words[0]); k++)
    if (!strcasecmp(raw, words[k]))
      PetscFunctionReturn(0);
  SETERRQ(comm, PETSC_ERR_ARG_WRONG,
          "%s %s: not a boolean; %s takes true or false (or nothing for true) (%s)", opt, raw, opt,
          text);
}

PetscErrorCode options_real(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], PetscReal current, PetscReal *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(po->comm, opt, raw, "a finite real number", text));
    PetscCall(options_check_real(po->comm, opt, raw, raw, "a finite real number", text));
  }
  PetscCall(PetscOptionsReal_Private(po, opt, text, man, current, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_int(PetscOptionItems *po, const char opt[], const char text[],
                           const char man[], PetscInt current, PetscInt *value, PetscBool *set,
                           PetscInt lb, PetscInt ub) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found)
    PetscCall(options_check_int(po->comm, opt, raw, lb, ub, text));
  PetscCall(PetscOptionsInt_Private(po, opt, text, man, current, value, set, lb, ub));
  PetscFunctionReturn(0);
}

PetscErrorCode options_bool(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], PetscBool current, PetscBool *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found)
    PetscCall(options_check_bool(po->comm, opt, raw, text));
  PetscCall(PetscOptionsBool_Private(po, opt, text, man, current, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_string(PetscOptionItems *po, const char opt[], const char text[],
                              const char man[], const char current[], char *value, size_t len,
                              PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(po->comm, opt, raw, "a text value", text));
    PetscCheck(strlen(raw) < len, po->comm, PETSC_ERR_ARG_SIZ, "%s %s: longer than %zu characters",
               opt, raw, len - 1);
  }
  PetscCall(PetscOptionsString_Private(po, opt, text, man, current, value, len, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_enum(PetscOptionItems *po, const char opt[], const char text[],
                            const char man[], const char *const *list, PetscEnum current,
                            PetscEnum *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  char choices[256] = "";
  int n = 0;
  PetscFunctionBeginUser;
  while (list[n])
    n++;
  n -= 2; /* PETSc enum lists end with the type name and the prefix */
  for (int k = 0; k < n; k++) {
    if (k)
      PetscCall(PetscStrlcat(choices, ", ", sizeof(choices)));
    PetscCall(PetscStrlcat(choices, list[k], sizeof(choices)));
  }
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found) {
    char takes[300];
    snprintf(takes, sizeof(takes), "one of %s", choices);
    PetscCall(options_need_value(po->comm, opt, raw, takes, text));
    int k = 0;
    while (k < n && strcasecmp(raw, list[k]))
      k++;
    PetscCheck(k < n, po->comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
               "%s %s: unknown value; %s takes %s (%s)", opt, raw, opt, takes, text);
  }
  PetscCall(PetscOptionsEnum_Private(po, opt, text, man, list, current, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_real_array(PetscOptionItems *po, const char opt[], const char text[],
                                  const char man[], PetscReal value[], PetscInt *n,
                                  PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found) {
    char takes[96];
    snprintf(takes, sizeof(takes), "up to %d finite real numbers separated by commas", (int)*n);
    PetscCall(options_need_value(po->comm, opt, raw, takes, text));
    PetscCall(options_check_list(po->comm, opt, raw, *n, 0, text));
  }
  PetscCall(PetscOptionsRealArray_Private(po, opt, text, man, value, n, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_string_array(PetscOptionItems *po, const char opt[], const char text[],
                                    const char man[], char *value[], PetscInt *n, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(po->options, po->prefix, opt, &raw, &found));
  if (found) {
    char takes[96];
    snprintf(takes, sizeof(takes), "up to %d names separated by commas", (int)*n);
    PetscCall(options_need_value(po->comm, opt, raw, takes, text));
    PetscCall(options_check_list(po->comm, opt, raw, *n, 1, text));
  }
  PetscCall(PetscOptionsStringArray_Private(po, opt, text, man, value, n, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_real(PetscOptions options, const char pre[], const char opt[],
                                PetscReal *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found) {
    PetscCall(options_need_value(PETSC_COMM_SELF, opt, raw, "a finite real number", "see -help"));
    PetscCall(
        options_check_real(PETSC_COMM_SELF, opt, raw, raw, "a finite real number", "see -help"));
  }
  PetscCall((PetscOptionsGetReal)(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_int(PetscOptions options, const char pre[], const char opt[],
                               PetscInt *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found)
    PetscCall(
        options_check_int(PETSC_COMM_SELF, opt, raw, PETSC_MIN_INT, PETSC_MAX_INT, "see -help"));
  PetscCall((PetscOptionsGetInt)(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode options_get_bool(PetscOptions options, const char pre[], const char opt[],
                                PetscBool *value, PetscBool *set) {
  const char *raw;
  PetscBool found;
  PetscFunctionBeginUser;
  PetscCall(options_raw(options, pre, opt, &raw, &found));
  if (found)
    PetscCall(options_check_bool(PETSC_COMM_SELF, opt, raw, "see -help"));
  PetscCall((PetscOptionsGetBool)(options, pre, opt, value, set));
  PetscFunctionReturn(0);
}
